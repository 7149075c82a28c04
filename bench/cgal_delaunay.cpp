// The floor for a CDT: CGAL's Delaunay triangulation of the same vertices (read from an OFF file),
// timed like sweep_bench (points inserted as a range: CGAL spatially sorts them).
//   cgal_delaunay FILE.off [--repeat K]   -> one JSON line
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  const int repeat = argc >= 4 && !std::strcmp(argv[2], "--repeat") ? std::atoi(argv[3]) : 1;
  std::ifstream in(argv[1]);
  std::string magic;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> magic >> nv >> nf >> ne;
  std::vector<K::Point_3> points(nv);
  for (auto& p : points) {
    double x, y, z;
    in >> x >> y >> z;
    p = K::Point_3(x, y, z);
  }
  std::vector<double> seconds;
  std::size_t cells = 0;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end());
    cells = dt.number_of_finite_cells();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("{\"points\": %zu, \"tets\": %zu, \"median_seconds\": %.4f, \"peak_rss_mb\": %.1f}\n", nv, cells,
              seconds[seconds.size() / 2], usage.ru_maxrss / 1024.0);
  return 0;
}
