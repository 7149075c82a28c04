// SortedKeys: a few keys looked up by binary search, for the maps of one vertex deletion
// (editable_cdt.cpp: its link faces, its new simplices' facets). A deletion has a few dozen keys and
// tens of thousands of deletions are tried, where a hash map's node per key cost more than a sort.
#pragma once
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace sweepcdt::detail {

// add() every key, with values in ascending order, sort() once, then find(). A key added twice
// maps to its first value (as unordered_map::emplace keeps the first): sorting the (key, value)
// pairs puts it first, without stable_sort's buffer.
template <class K>
class SortedKeys {
 public:
  void add(const K& key, uint32_t value) { entries_.push_back({key, value}); }
  void sort() { std::sort(entries_.begin(), entries_.end()); }
  const uint32_t* find(const K& key) const {
    const auto it = std::lower_bound(entries_.begin(), entries_.end(), key, [](const auto& e, const K& k) { return e.first < k; });
    return it != entries_.end() && it->first == key ? &it->second : nullptr;
  }
  bool contains(const K& key) const { return find(key) != nullptr; }

 private:
  std::vector<std::pair<K, uint32_t>> entries_;
};

}  // namespace sweepcdt::detail
