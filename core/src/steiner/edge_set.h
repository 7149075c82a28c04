// EdgeSet: a set of edge keys (facet_groups.h: edge_key) in a flat open-addressing table — linear
// probing, at most three quarters full, an erase shifting its probe run back (no tombstones), as
// TupleMap does. Refinement looks its segments up for every edge it visits, adds and removes them
// as it splits them, and builds and frees the set again for each lazy attempt: a std::unordered_set
// allocated a node per segment for that. Iteration order is the table's (callers that need an
// order sort).
#pragma once
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <vector>

namespace sweepcdt::detail {

class EdgeSet {
 public:
  EdgeSet() = default;
  template <class It>
  EdgeSet(It first, It last) {
    insert(first, last);
  }
  EdgeSet(std::initializer_list<uint64_t> keys) { insert(keys.begin(), keys.end()); }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t count(uint64_t key) const { return find_slot(key) != kMissing; }

  // Whether key was not there before.
  bool insert(uint64_t key) {
    if (4 * (size_ + 1) > 3 * keys_.size()) rehash(keys_.empty() ? 16 : 2 * keys_.size());
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return false;
      if (keys_[i] == kEmpty) {
        keys_[i] = key;
        ++size_;
        return true;
      }
    }
  }
  template <class It>
  void insert(It first, It last) {
    for (; first != last; ++first) insert(*first);
  }

  // Whether key was there. The entries after it in its probe run that hashed at or before its slot
  // move back into the gap, so that every probe run stays unbroken.
  bool erase(uint64_t key) {
    std::size_t gap = find_slot(key);
    if (gap == kMissing) return false;
    for (std::size_t j = (gap + 1) & mask_; keys_[j] != kEmpty; j = (j + 1) & mask_) {
      const std::size_t home = slot(keys_[j]);
      const bool stays = gap < j ? (gap < home && home <= j) : (gap < home || home <= j);
      if (stays) continue;
      keys_[gap] = keys_[j];
      gap = j;
    }
    keys_[gap] = kEmpty;
    --size_;
    return true;
  }

  class const_iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = uint64_t;
    using difference_type = std::ptrdiff_t;
    using pointer = const uint64_t*;
    using reference = const uint64_t&;
    const_iterator(const uint64_t* at, const uint64_t* end) : at_(at), end_(end) { skip(); }
    reference operator*() const { return *at_; }
    const_iterator& operator++() {
      ++at_;
      skip();
      return *this;
    }
    const_iterator operator++(int) {
      const_iterator before = *this;
      ++*this;
      return before;
    }
    bool operator==(const const_iterator& other) const { return at_ == other.at_; }

   private:
    void skip() {
      while (at_ != end_ && *at_ == kEmpty) ++at_;
    }
    const uint64_t* at_;
    const uint64_t* end_;
  };
  const_iterator begin() const { return {keys_.data(), keys_.data() + keys_.size()}; }
  const_iterator end() const { return {keys_.data() + keys_.size(), keys_.data() + keys_.size()}; }

 private:
  // No edge has this key: it would join vertex 2^32 - 1 to itself.
  static constexpr uint64_t kEmpty = ~uint64_t{0};
  static constexpr std::size_t kMissing = ~std::size_t{0};

  std::size_t slot(uint64_t key) const {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdull;
    key ^= key >> 33;
    return static_cast<std::size_t>(key) & mask_;
  }
  std::size_t find_slot(uint64_t key) const {
    if (keys_.empty()) return kMissing;
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return i;
      if (keys_[i] == kEmpty) return kMissing;
    }
  }
  void rehash(std::size_t capacity) {
    std::vector<uint64_t> old(capacity, kEmpty);
    old.swap(keys_);
    mask_ = capacity - 1;
    size_ = 0;
    for (const uint64_t key : old)
      if (key != kEmpty) insert(key);
  }

  std::vector<uint64_t> keys_;
  std::size_t mask_ = 0, size_ = 0;
};

}  // namespace sweepcdt::detail
