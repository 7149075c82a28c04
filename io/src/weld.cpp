// weld(): merge points with exactly equal coordinates — never by tolerance, which would move geometry.
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "sweepcdt/io/surface.h"

namespace sweepcdt::io {

namespace {

// A point's coordinates as bits, -0 as +0 (== holds between them, so they weld).
std::array<uint64_t, 3> coordinate_bits(const double* x) {
  std::array<uint64_t, 3> bits;
  for (int k = 0; k < 3; ++k) bits[k] = std::bit_cast<uint64_t>(x[k] + 0.0);
  return bits;
}

uint64_t hash_of(const std::array<uint64_t, 3>& bits) {
  uint64_t h = 0x9e3779b97f4a7c15ull;
  for (const uint64_t b : bits) h = (h ^ b) * 0xbf58476d1ce4e5b9ull, h ^= h >> 31;
  return h;
}

}  // namespace

Surface weld(const Soup& soup) {
  const std::size_t n = soup.num_points();
  auto p = [&](uint32_t i) { return soup.points.data() + 3 * std::size_t{i}; };
  // Each point's representative: the smallest index with the same coordinates. An open-addressing
  // table over the coordinates' bits, filled in index order (a sort by coordinates took a tenth of
  // a 327k-triangle STL's run: every triangle brings its own three points).
  constexpr uint32_t kEmpty = UINT32_MAX;
  std::size_t slots = 16;
  while (slots < 2 * n) slots *= 2;
  std::vector<uint32_t> table(slots, kEmpty);
  std::vector<uint32_t> representative(n);
  for (uint32_t i = 0; i < n; ++i) {
    const std::array<uint64_t, 3> bits = coordinate_bits(p(i));
    std::size_t slot = hash_of(bits) & (slots - 1);
    while (table[slot] != kEmpty && coordinate_bits(p(table[slot])) != bits) slot = (slot + 1) & (slots - 1);
    if (table[slot] == kEmpty) table[slot] = i;
    representative[i] = table[slot];
  }
  table = {};  // release before the output grows

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
