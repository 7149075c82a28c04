// Internal: hashing of sorted vertex tuples (facet and ridge keys) for the gift-wrapping dictionary.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace sweepcdt::detail {

// Sorts a small tuple in place: an insertion sort, for the 2 to 6 ids of a facet or ridge key,
// where std::sort's set-up costs more than the sorting.
template <std::size_t N>
void sort_tuple(std::array<uint32_t, N>& a) {
  for (std::size_t i = 1; i < N; ++i)
    for (std::size_t j = i; j > 0 && a[j] < a[j - 1]; --j) std::swap(a[j], a[j - 1]);
}

// Whether the order of the distinct ids `ids` is an odd permutation of the ascending one: two
// orders of one simplex's vertices give orientations of the same sign exactly when they agree here.
template <std::size_t N>
bool odd_permutation(const std::array<uint32_t, N>& ids) {
  bool odd = false;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) odd ^= ids[i] > ids[j];
  return odd;
}

struct TupleHash {
  template <std::size_t N>
  std::size_t operator()(const std::array<uint32_t, N>& key) const {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (uint32_t v : key) {
      h ^= v;
      h *= 0xff51afd7ed558ccdull;
      h ^= h >> 33;
    }
    return static_cast<std::size_t>(h);
  }
};

// Equal tuples, element by element: std::array's == calls memcmp, a library call per comparison on
// the hot paths of hashing and grouping facets.
template <std::size_t N>
inline bool same_tuple(const std::array<uint32_t, N>& a, const std::array<uint32_t, N>& b) {
  for (std::size_t i = 0; i < N; ++i)
    if (a[i] != b[i]) return false;
  return true;
}

}  // namespace sweepcdt::detail
