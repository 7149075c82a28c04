// EdgeSet: a set of edge keys (facet_groups.h: edge_key) in a flat table (flat_set.h). Refinement
// looks its segments up for every edge it visits, adds and removes them as it splits them, and
// builds the set again for each lazy attempt.
#pragma once
#include <cstddef>
#include <cstdint>

#include "../flat_set.h"

namespace sweepcdt::detail {

struct EdgeKeyTraits {
  using Key = uint64_t;
  // No edge has this key: it would join vertex 2^32 - 1 to itself.
  static constexpr Key kEmpty = ~uint64_t{0};
  static std::size_t hash(uint64_t key) {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdull;
    key ^= key >> 33;
    return static_cast<std::size_t>(key);
  }
};
using EdgeSet = FlatSet<EdgeKeyTraits>;

}  // namespace sweepcdt::detail
