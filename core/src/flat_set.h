// FlatSet<Traits>: a set of small keys in one flat open-addressing table — linear probing,
// power-of-two capacity at most three quarters full, an erase shifting its probe run back (no
// tombstones, as TupleMap's erase does), no allocation per entry. Traits gives the key type `Key`,
// `kEmpty` (a key no caller ever stores: it marks a free slot) and `hash(key)`. Refinement's sets
// (steiner/edge_set.h, steiner/coordinate_set.h) are built and freed again for each lazy attempt,
// where node-based std::unordered_sets allocated an entry each. Iteration follows the table (callers
// that need an order sort).
#pragma once
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <vector>

namespace sweepcdt::detail {

template <class Traits>
class FlatSet {
 public:
  using Key = typename Traits::Key;

  FlatSet() = default;
  template <class It>
  FlatSet(It first, It last) {
    insert(first, last);
  }
  FlatSet(std::initializer_list<Key> keys) { insert(keys.begin(), keys.end()); }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t count(const Key& key) const { return find_slot(key) != kMissing; }

  // Room for n keys without growing.
  void reserve(std::size_t n) {
    if (capacity_for(n) > keys_.size()) rehash(capacity_for(n));
  }

  // Whether key was not there before.
  bool insert(const Key& key) {
    if (4 * (size_ + 1) > 3 * keys_.size()) rehash(capacity_for(size_ + 1));
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return false;
      if (keys_[i] == Traits::kEmpty) {
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
  bool erase(const Key& key) {
    std::size_t gap = find_slot(key);
    if (gap == kMissing) return false;
    for (std::size_t j = (gap + 1) & mask_; keys_[j] != Traits::kEmpty; j = (j + 1) & mask_) {
      const std::size_t home = slot(keys_[j]);
      const bool stays = gap < j ? (gap < home && home <= j) : (gap < home || home <= j);
      if (stays) continue;
      keys_[gap] = keys_[j];
      gap = j;
    }
    keys_[gap] = Traits::kEmpty;
    --size_;
    return true;
  }

  class const_iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = Key;
    using difference_type = std::ptrdiff_t;
    using pointer = const Key*;
    using reference = const Key&;
    const_iterator(const Key* at, const Key* end) : at_(at), end_(end) { skip(); }
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
      while (at_ != end_ && *at_ == Traits::kEmpty) ++at_;
    }
    const Key* at_;
    const Key* end_;
  };
  const_iterator begin() const { return {keys_.data(), keys_.data() + keys_.size()}; }
  const_iterator end() const { return {keys_.data() + keys_.size(), keys_.data() + keys_.size()}; }

 private:
  static constexpr std::size_t kMissing = ~std::size_t{0};

  static std::size_t capacity_for(std::size_t n) {
    std::size_t c = 16;
    while (3 * c < 4 * n) c *= 2;
    return c;
  }
  std::size_t slot(const Key& key) const { return Traits::hash(key) & mask_; }
  std::size_t find_slot(const Key& key) const {
    if (keys_.empty()) return kMissing;
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return i;
      if (keys_[i] == Traits::kEmpty) return kMissing;
    }
  }
  void rehash(std::size_t capacity) {
    std::vector<Key> old(capacity, Traits::kEmpty);
    old.swap(keys_);
    mask_ = capacity - 1;
    size_ = 0;
    for (const Key& key : old)
      if (key != Traits::kEmpty) insert(key);
  }

  std::vector<Key> keys_;
  std::size_t mask_ = 0, size_ = 0;
};

}  // namespace sweepcdt::detail
