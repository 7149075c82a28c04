// IdSet: a set of vertex or simplex ids for one vertex deletion's searches (a star's simplices, its
// vertices), open addressing in a power-of-two table kept at most half full: no node per id as in
// std::unordered_set, and no scan of the list found so far, which grew quadratically in the stars of
// hundreds of tetrahedra on thin walls (perforated_tube_fine.stl).
#pragma once
#include <cstdint>
#include <vector>

namespace sweepcdt::detail {

class IdSet {
 public:
  explicit IdSet(std::size_t expected = 32) {
    std::size_t capacity = 64;
    while (capacity < 2 * expected) capacity *= 2;
    table_.assign(capacity, kEmpty);
  }

  // Adds id (never kEmpty); true when it was not there.
  bool insert(uint32_t id) {
    if (2 * (size_ + 1) > table_.size()) grow();
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = slot(id);; i = (i + 1) & mask) {
      if (table_[i] == id) return false;
      if (table_[i] == kEmpty) {
        table_[i] = id;
        ++size_;
        return true;
      }
    }
  }

  std::size_t size() const { return size_; }

 private:
  static constexpr uint32_t kEmpty = 0xffffffffu;
  // Fibonacci hashing: ids close together (a star's simplices often are) spread over the table.
  std::size_t slot(uint32_t id) const { return (uint64_t{id} * 0x9E3779B97F4A7C15ull >> 32) & (table_.size() - 1); }
  void grow() {
    std::vector<uint32_t> old(table_.size() * 2, kEmpty);
    old.swap(table_);
    size_ = 0;
    for (const uint32_t id : old)
      if (id != kEmpty) insert(id);
  }

  std::vector<uint32_t> table_;
  std::size_t size_ = 0;
};

}  // namespace sweepcdt::detail
