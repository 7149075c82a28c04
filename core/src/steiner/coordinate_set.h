// Every point's coordinates, bit for bit, for refinement's question whether a new Steiner point
// rounds onto a point that is there already (refine.cpp: then it takes another parameter). A flat
// open-addressing set: linear probing, at most three quarters full (about the memory of the
// node-based set it replaces), no allocation per point. A std::unordered_set's node per point,
// built again for each lazy attempt and freed after it, was a third of the hash-table and
// allocator work of refinement on a 75k-triangle scan.
#pragma once
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sweepcdt::detail {

class CoordinateSet {
 public:
  bool empty() const { return size_ == 0; }

  // Room for n points without growing.
  void reserve(std::size_t n) {
    if (capacity_for(n) > keys_.size()) rehash(capacity_for(n));
  }

  bool contains(const double* x) const {
    if (keys_.empty()) return false;
    const Key k = key_of(x);
    for (std::size_t i = slot(k);; i = (i + 1) & mask_) {
      if (keys_[i] == kEmpty) return false;
      if (keys_[i] == k) return true;
    }
  }

  // Adds x's coordinates unless they are there.
  void insert(const double* x) {
    if (4 * (size_ + 1) > 3 * keys_.size()) rehash(capacity_for(size_ + 1));
    place(key_of(x));
  }

 private:
  using Key = std::array<uint64_t, 3>;
  // A NaN's bits three times: no point has them (the PLC check refuses coordinates that are not finite).
  static constexpr Key kEmpty = {~uint64_t{0}, ~uint64_t{0}, ~uint64_t{0}};

  static Key key_of(const double* x) {
    return {std::bit_cast<uint64_t>(x[0]), std::bit_cast<uint64_t>(x[1]), std::bit_cast<uint64_t>(x[2])};
  }
  static std::size_t capacity_for(std::size_t n) {
    std::size_t c = 16;
    while (3 * c < 4 * n) c *= 2;
    return c;
  }
  std::size_t slot(const Key& k) const {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (const uint64_t w : k) {
      h ^= w;
      h *= 0xff51afd7ed558ccdull;
      h ^= h >> 33;
    }
    return static_cast<std::size_t>(h) & mask_;
  }
  void place(const Key& k) {
    for (std::size_t i = slot(k);; i = (i + 1) & mask_) {
      if (keys_[i] == k) return;
      if (keys_[i] == kEmpty) {
        keys_[i] = k;
        ++size_;
        return;
      }
    }
  }
  void rehash(std::size_t capacity) {
    std::vector<Key> old(capacity, kEmpty);
    old.swap(keys_);
    mask_ = capacity - 1;
    size_ = 0;
    for (const Key& k : old)
      if (k != kEmpty) place(k);
  }

  std::vector<Key> keys_;
  std::size_t mask_ = 0, size_ = 0;
};

}  // namespace sweepcdt::detail
