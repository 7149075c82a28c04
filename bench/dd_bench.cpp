// Times cdt<D>() on random points in the unit D-cube (no constraints: the domain is the convex hull,
// so the result is the Delaunay triangulation under the §6 perturbation) and prints one JSON line;
// optionally writes the points so that cgal_delaunay_dd can triangulate the same ones (issue 16:
// the d = 4, 5 sweeps against CGAL's Delaunay_triangulation). bench/run_dd.py runs both.
//
//   dd_bench D N [--algorithm sweep-sphere|sweep-plane|giftwrap|cavity-sweep] [--repeat K]
//                [--points PATH]     (D = 2..5; PATH: N lines of D coordinates, then exit)
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "sweepcdt/cdt.h"
#include "timed_cdt.h"

using namespace sweepcdt;

namespace {

std::vector<double> random_points(int dimension, int n) {
  std::mt19937_64 rng(7 + dimension);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> points(static_cast<std::size_t>(dimension) * n);
  for (double& x : points) x = u(rng);
  return points;
}

template <int D>
int run(int n, const Options& options, int repeat) {
  Plc<D> plc;
  plc.points = random_points(D, n);
  const bench::TimedCdt t = bench::timed_cdt(plc, options, repeat);
  const CdtStatistics& stats = t.stats;
  std::printf("{\"dimension\": %d, \"points\": %d, \"algorithm\": \"%s\", \"simplices\": %zu, \"median_seconds\": %.4f, "
              "\"check\": %.4f, \"setup\": %.4f, \"build\": %.4f, \"finish\": %.4f, \"peak_rss_mb\": %.1f, \"error\": \"%s\"}\n",
              D, n, to_string(stats.algorithm), t.simplices, t.median_seconds, stats.seconds_check, stats.seconds_setup,
              stats.seconds_build, stats.seconds_finish, t.peak_rss_mb, t.error.c_str());
  return t.error.empty() ? 0 : 4;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s D N [--algorithm A] [--repeat K] [--points PATH]\n", argv[0]);
    return 2;
  }
  const int dimension = std::atoi(argv[1]), n = std::atoi(argv[2]);
  Options options;
  options.algorithm = Algorithm::SweepSphere;
  int repeat = 1;
  for (int i = 3; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--algorithm")) {
      const auto a = algorithm_named(argv[i + 1]);
      if (!a) return std::fprintf(stderr, "unknown algorithm %s\n", argv[i + 1]), 2;
      options.algorithm = *a;
    } else if (!std::strcmp(argv[i], "--repeat")) {
      repeat = std::atoi(argv[i + 1]);
    } else if (!std::strcmp(argv[i], "--points")) {
      FILE* f = std::fopen(argv[i + 1], "w");
      if (!f) return 5;
      const std::vector<double> points = random_points(dimension, n);
      for (std::size_t k = 0; k < points.size(); ++k) std::fprintf(f, "%.17g%c", points[k], (k + 1) % dimension ? ' ' : '\n');
      return std::fclose(f) == 0 ? 0 : 5;
    }
  }
  switch (dimension) {
    case 2: return run<2>(n, options, repeat);
    case 3: return run<3>(n, options, repeat);
    case 4: return run<4>(n, options, repeat);
    case 5: return run<5>(n, options, repeat);
    default: return std::fprintf(stderr, "D must be 2..5\n"), 2;
  }
}
