// Every point's coordinates, bit for bit, for refinement's question whether a new Steiner point
// rounds onto a point that is there already (refine.cpp: then it takes another parameter), in a flat
// table (flat_set.h; at three quarters full about the memory of the node-based set it replaced). A
// std::unordered_set's node per point, built again for each lazy attempt and freed after it, was a
// third of the hash-table and allocator work of refinement on a 75k-triangle scan.
#pragma once
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "../flat_set.h"

namespace sweepcdt::detail {

struct CoordinateTraits {
  using Key = std::array<uint64_t, 3>;
  // A NaN's bits three times: no point has them (the PLC check refuses coordinates that are not finite).
  static constexpr Key kEmpty = {~uint64_t{0}, ~uint64_t{0}, ~uint64_t{0}};
  static std::size_t hash(const Key& k) {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (const uint64_t w : k) {
      h ^= w;
      h *= 0xff51afd7ed558ccdull;
      h ^= h >> 33;
    }
    return static_cast<std::size_t>(h);
  }
};

class CoordinateSet {
 public:
  bool empty() const { return set_.empty(); }
  void reserve(std::size_t n) { set_.reserve(n); }  // room for n points without growing
  bool contains(const double* x) const { return set_.count(key_of(x)) != 0; }
  void insert(const double* x) { set_.insert(key_of(x)); }  // unless there

 private:
  static CoordinateTraits::Key key_of(const double* x) {
    return {std::bit_cast<uint64_t>(x[0]), std::bit_cast<uint64_t>(x[1]), std::bit_cast<uint64_t>(x[2])};
  }
  FlatSet<CoordinateTraits> set_;
};

}  // namespace sweepcdt::detail
