// Times cdt() with Steiner points on a surface file and prints one JSON line; optionally writes the
// welded surface as OFF so bench/run_steiner.sh can hand the same input to TetGen.
//
//   steiner_bench FILE [--facets triangles|coplanar] [--steiner auto|none] [--algorithm A] [--off PATH]
//                      [--count-only]    (only the welded counts, and the OFF file: bench/run_cad.py)
//                      [--cad-noise F]   (first move coordinates by a few ulps with probability F:
//                                         tests/support/cad_noise.h, seed 1, as the tests do)
//                      [--threads N]     (Options::threads; default 0, every hardware thread)
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "sweepcdt/cdt.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/write_surface.h"
#include "cad_noise.h"

using namespace sweepcdt;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE [--facets triangles|coplanar] [--steiner auto|none] [--algorithm A] [--off PATH] [--threads N]\n", argv[0]);
    return 2;
  }
  Options options;
  options.steiner = SteinerMode::Auto;
  std::string off;
  bool count_only = false;
  double noise = 0;
  for (int i = 2; i < argc; i += 2) {
    if (std::string(argv[i]) == "--count-only") {
      count_only = true;
      --i;
      continue;
    }
    if (i + 1 >= argc) break;
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--facets") options.facets = value == "coplanar" ? FacetMode::Coplanar : FacetMode::Triangles;
    else if (flag == "--steiner") options.steiner = value == "none" ? SteinerMode::None : SteinerMode::Auto;
    else if (flag == "--algorithm")
      options.algorithm = value == "giftwrap" ? Algorithm::GiftWrap : value == "sweep-plane" ? Algorithm::SweepPlane : Algorithm::SweepSphere;
    else if (flag == "--off") off = value;
    else if (flag == "--cad-noise") noise = std::stod(value);
    else if (flag == "--threads") options.threads = static_cast<unsigned>(std::stoul(value));
  }
  Plc<3> plc = io::import_plc(argv[1]);
  if (noise > 0) plc = testing::with_cad_noise(std::move(plc), noise, 1);
  if (!off.empty()) io::write_surface(off, plc, io::Format::Off);
  if (count_only) {
    std::printf("{\"file\": \"%s\", \"points\": %zu, \"triangles\": %zu}\n", argv[1], plc.num_points(), plc.num_simplices());
    return 0;
  }
  CdtStatistics stats;
  options.statistics = &stats;
  std::string error;
  std::size_t tets = 0;
  const auto start = std::chrono::steady_clock::now();
  try {
    tets = cdt(plc, options).num_simplices();
  } catch (const std::exception& e) {
    error = e.what();
    for (char& c : error)
      if (c == '"' || c == '\\') c = '\'';
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "{\"file\": \"%s\", \"points\": %zu, \"triangles\": %zu, \"facets\": %lu, \"steiner_points\": %lu, \"rounds\": %lu, "
      "\"flips\": %lu, \"tets\": %zu, \"seconds\": %.3f, \"seconds_setup\": %.3f, \"seconds_build\": %.3f, "
      "\"seconds_finish\": %.3f, \"error\": \"%s\"}\n",
      argv[1], plc.num_points(), plc.num_simplices(), static_cast<unsigned long>(stats.facets),
      static_cast<unsigned long>(stats.steiner_points), static_cast<unsigned long>(stats.steiner_rounds),
      static_cast<unsigned long>(stats.facet_flips), tets, seconds, stats.seconds_setup, stats.seconds_build,
      stats.seconds_finish, error.c_str());
  return error.empty() ? 0 : 1;
}
