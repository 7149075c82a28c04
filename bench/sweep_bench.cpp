// Times cdt() on a generated closed surface and prints one JSON line; optionally writes the surface
// as OFF so bench/run_sweep.py can hand the same input to TetGen and CGAL.
//
//   sweep_bench SURFACE SIZE [--algorithm cavity-sweep|sweep-sphere|sweep-plane|giftwrap] [--repeat K]
//               [--threads N] [--off PATH]
//   SURFACE: icosphere | cospherical | torus | cavity | cube-points (random points, convex hull)
//   SIZE:    icosphere/cospherical/cavity: subdivision levels; torus: quads around; cube-points: points

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "surfaces.h"
#include "sweepcdt/cdt.h"
#include "timed_cdt.h"

using namespace sweepcdt;

namespace {

Plc<3> make(const std::string& surface, int size, bench::Mesh& mesh) {
  if (surface == "icosphere") {
    mesh = bench::icosphere(size);
    bench::jitter(mesh, 1e-3, 1);
  } else if (surface == "cospherical") {
    mesh = bench::cospherical(size);
  } else if (surface == "torus") {
    mesh = bench::torus(size, std::max(3, size / 3));
    bench::jitter(mesh, 1e-4, 2);
  } else if (surface == "cavity") {
    bench::Mesh outer = bench::icosphere(size), inner = bench::icosphere(std::max(0, size - 1));
    bench::jitter(outer, 1e-3, 3);
    bench::jitter(inner, 1e-3, 4);
    mesh = bench::with_cavity(outer, inner, 0.5);
  } else if (surface == "cube-points") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    Plc<3> plc;
    for (int i = 0; i < 3 * size; ++i) plc.points.push_back(u(rng));
    return plc;
  } else {
    throw std::invalid_argument("unknown surface " + surface);
  }
  return bench::to_plc(mesh);
}

Algorithm parse_algorithm(const std::string& s) {
  if (s == "sweep-sphere") return Algorithm::SweepSphere;
  if (s == "sweep-plane") return Algorithm::SweepPlane;
  if (s == "giftwrap") return Algorithm::GiftWrap;
  if (s == "cavity-sweep") return Algorithm::CavitySweep;
  throw std::invalid_argument("unknown algorithm " + s);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s SURFACE SIZE [--algorithm A] [--repeat K] [--off PATH]\n", argv[0]);
    return 2;
  }
  Options options;
  int repeat = 1;
  std::string off;
  for (int i = 3; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--algorithm")) options.algorithm = parse_algorithm(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat")) repeat = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--off")) off = argv[i + 1];
    else if (!std::strcmp(argv[i], "--threads")) options.threads = static_cast<unsigned>(std::atoi(argv[i + 1]));
  }
  bench::Mesh mesh;
  const Plc<3> plc = make(argv[1], std::atoi(argv[2]), mesh);
  if (!off.empty()) return bench::write_off(mesh, off) ? 0 : 5;

  const bench::TimedCdt t = bench::timed_cdt(plc, options, repeat);
  const CdtStatistics& stats = t.stats;
  std::printf("{\"surface\": \"%s\", \"triangles\": %zu, \"points\": %zu, \"algorithm\": \"%s\", \"tets\": %zu, "
              "\"median_seconds\": %.4f, \"check\": %.4f, \"setup\": %.4f, \"build\": %.4f, \"finish\": %.4f, "
              "\"queue_pops\": %lu, \"drop_moves\": %lu, \"peak_rss_mb\": %.1f, \"error\": \"%s\"}\n",
              argv[1], plc.num_simplices(), plc.num_points(), to_string(stats.algorithm), t.simplices, t.median_seconds,
              stats.seconds_check, stats.seconds_setup, stats.seconds_build, stats.seconds_finish,
              static_cast<unsigned long>(stats.queue_pops), static_cast<unsigned long>(stats.drop_moves), t.peak_rss_mb,
              t.error.c_str());
  return t.error.empty() ? 0 : 4;
}
