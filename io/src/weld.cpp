// weld(): merge points with exactly equal coordinates — never by tolerance, which would move geometry.
#include <algorithm>
#include <numeric>

#include "sweepcdt/io/surface.h"

namespace sweepcdt::io {

Surface weld(const Soup& soup) {
  const std::size_t n = soup.num_points();
  auto p = [&](uint32_t i) { return soup.points.data() + 3 * std::size_t{i}; };
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  // Lexicographic by coordinates, ties by index so the representative is the smallest index.
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const double *pa = p(a), *pb = p(b);
    for (int k = 0; k < 3; ++k)
      if (pa[k] != pb[k]) return pa[k] < pb[k];
    return a < b;
  });
  std::vector<uint32_t> representative(n);
  for (std::size_t i = 0; i < n; ++i) {
    const uint32_t a = order[i];
    const bool same_as_previous = i > 0 && std::equal(p(a), p(a) + 3, p(order[i - 1]));
    representative[a] = same_as_previous ? representative[order[i - 1]] : a;
  }
  order = {};  // release before the output grows

  Surface surface;
  surface.file = soup.file;
  surface.format = soup.format;
  surface.points_in_file = n;
  surface.triangles.resize(soup.triangles.size());
  constexpr uint32_t kUnset = UINT32_MAX;
  std::vector<uint32_t> new_id(n, kUnset);
  for (std::size_t c = 0; c < soup.triangles.size(); ++c) {
    const uint32_t r = representative[soup.triangles[c]];
    if (new_id[r] == kUnset) {
      new_id[r] = static_cast<uint32_t>(surface.num_points());
      surface.points.insert(surface.points.end(), p(r), p(r) + 3);
    }
    surface.triangles[c] = new_id[r];
  }
  return surface;
}

}  // namespace sweepcdt::io
