// CGAL's d-dimensional Delaunay triangulation (Epick_d, static dimension 4 or 5) of the points
// dd_bench wrote, timed like dd_bench (points inserted as a range: CGAL spatially sorts them).
//   cgal_delaunay_dd D FILE [--repeat K]   -> one JSON line
#include <CGAL/Delaunay_triangulation.h>
#include <CGAL/Epick_d.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

namespace {

template <int D>
int run(const char* file, int repeat) {
  using K = CGAL::Epick_d<CGAL::Dimension_tag<D>>;
  using Point = typename K::Point_d;
  std::ifstream in(file);
  std::vector<Point> points;
  std::vector<double> c(D);
  while (true) {
    for (double& x : c) in >> x;
    if (!in) break;
    points.emplace_back(c.begin(), c.end());
  }
  std::vector<double> seconds;
  std::size_t cells = 0;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    CGAL::Delaunay_triangulation<K> dt(D);
    dt.insert(points.begin(), points.end());
    cells = dt.number_of_finite_full_cells();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("{\"dimension\": %d, \"points\": %zu, \"simplices\": %zu, \"median_seconds\": %.4f, \"peak_rss_mb\": %.1f}\n", D,
              points.size(), cells, seconds[seconds.size() / 2], usage.ru_maxrss / 1024.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return 2;
  const int repeat = argc >= 5 && !std::strcmp(argv[3], "--repeat") ? std::atoi(argv[4]) : 1;
  switch (std::atoi(argv[1])) {
    case 4: return run<4>(argv[2], repeat);
    case 5: return run<5>(argv[2], repeat);
    default: return 2;
  }
}
