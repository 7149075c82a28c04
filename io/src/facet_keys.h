// Lookup of a PLC's constraining simplices by their vertex set (sorted ids, so the order a
// triangulation lists a facet's vertices in does not matter). Sorted vector + binary search:
// deterministic, no per-element allocation.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::io::detail {

template <int D>
class SimplexKeys {
 public:
  using Key = std::array<uint32_t, D>;

  explicit SimplexKeys(const Plc<D>& plc) : plc_(plc) {
    entries_.reserve(plc.num_simplices());
    for (std::size_t j = 0; j < plc.num_simplices(); ++j) entries_.push_back({key(plc.simplex(j)), static_cast<uint32_t>(j)});
    std::sort(entries_.begin(), entries_.end());
  }
  static Key key(const uint32_t* ids) {
    Key k;
    std::copy_n(ids, D, k.begin());
    std::sort(k.begin(), k.end());
    return k;
  }
  // The index of the constraining simplex with these vertices, or kNone.
  uint32_t index_of(const uint32_t* ids) const {
    const Entry probe{key(ids), 0};
    const auto it = std::lower_bound(entries_.begin(), entries_.end(), probe,
                                     [](const Entry& a, const Entry& b) { return a.key < b.key; });
    return it != entries_.end() && it->key == probe.key ? it->index : kNone;
  }
  // Its tag (the index when the PLC has no tags), or kNone.
  uint32_t tag_of(const uint32_t* ids) const {
    const uint32_t j = index_of(ids);
    if (j == kNone) return kNone;
    return plc_.tags.size() == plc_.num_simplices() ? plc_.tags[j] : j;
  }

 private:
  struct Entry {
    Key key;
    uint32_t index;
    bool operator<(const Entry& o) const { return key != o.key ? key < o.key : index < o.index; }
  };
  const Plc<D>& plc_;
  std::vector<Entry> entries_;
};

using TriangleKeys = SimplexKeys<3>;

}  // namespace sweepcdt::io::detail
