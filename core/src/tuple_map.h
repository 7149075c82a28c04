// TupleMap<N>: a flat open-addressing hash map from sorted vertex-id tuples (faces, ridges) to
// uint32_t, for the sweep's dictionaries (paper §3: "best implemented as a hash table"). Linear
// probing, power-of-two capacity kept at most half full; erase() shifts the entries after a removed
// one back (no tombstones: the sweep never erases, EditableCdt's constraint map does at each
// deletion). No per-entry allocation, unlike std::unordered_map.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "facet_hash.h"

namespace sweepcdt::detail {

template <std::size_t N>
class TupleMap {
 public:
  using Key = std::array<uint32_t, N>;
  static constexpr uint32_t kAbsent = 0xffffffffu;

  explicit TupleMap(std::size_t expected = 16) { rehash(capacity_for(expected)); }

  // The value for key, or kAbsent.
  uint32_t find(const Key& key) const {
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (values_[i] == kAbsent) return kAbsent;
      if (same_tuple(keys_[i], key)) return values_[i];
    }
  }

  // Inserts key -> value unless present; returns the value stored and whether it was inserted.
  std::pair<uint32_t, bool> emplace(const Key& key, uint32_t value) {
    if (2 * (size_ + 1) > values_.size()) rehash(values_.size() * 2);
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (values_[i] == kAbsent) {
        keys_[i] = key;
        values_[i] = value;
        ++size_;
        return {value, true};
      }
      if (same_tuple(keys_[i], key)) return {values_[i], false};
    }
  }

  bool contains(const Key& key) const { return find(key) != kAbsent; }

  // Removes key (if present): the entries of its probe run that hashed at or before its slot move
  // back into the gap, so every probe run stays unbroken.
  bool erase(const Key& key) {
    std::size_t gap = slot(key);
    for (;; gap = (gap + 1) & mask_) {
      if (values_[gap] == kAbsent) return false;
      if (same_tuple(keys_[gap], key)) break;
    }
    for (std::size_t j = (gap + 1) & mask_; values_[j] != kAbsent; j = (j + 1) & mask_) {
      const std::size_t home = slot(keys_[j]);
      // The entry at j stays when its home lies cyclically in (gap, j]: probing from there never passes the gap.
      const bool stays = gap < j ? (gap < home && home <= j) : (gap < home || home <= j);
      if (stays) continue;
      keys_[gap] = keys_[j];
      values_[gap] = values_[j];
      gap = j;
    }
    values_[gap] = kAbsent;
    --size_;
    return true;
  }

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return values_.size(); }

  // Empties the map and keeps its capacity (a map reused for many small sets allocates once).
  void clear() {
    std::fill(values_.begin(), values_.end(), kAbsent);
    size_ = 0;
  }

 private:
  static std::size_t capacity_for(std::size_t expected) {
    std::size_t c = 16;
    while (c < 2 * expected) c *= 2;
    return c;
  }
  std::size_t slot(const Key& key) const { return TupleHash{}(key) & mask_; }

  void rehash(std::size_t capacity) {
    std::vector<Key> keys(capacity);
    std::vector<uint32_t> values(capacity, kAbsent);
    keys.swap(keys_);
    values.swap(values_);
    mask_ = capacity - 1;
    size_ = 0;
    for (std::size_t i = 0; i < values.size(); ++i)
      if (values[i] != kAbsent) emplace(keys[i], values[i]);
  }

  std::vector<Key> keys_;
  std::vector<uint32_t> values_;
  std::size_t mask_ = 0, size_ = 0;
};

}  // namespace sweepcdt::detail
