#include "regions.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include "facets.h"
#include "parallel.h"
#include "tuple_map.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::detail {

template <int D>
void assign_regions(Triangulation<D>& tri, const Plc<D>& plc, unsigned threads) {
  const std::size_t s = tri.num_simplices();
  TupleMap<D> constraints(plc.num_simplices());
  for (std::size_t j = 0; j < plc.num_simplices(); ++j) {
    FacetKey<D> k;
    std::copy_n(plc.simplex(j), D, k.begin());
    std::sort(k.begin(), k.end());
    constraints.emplace(k, 0);
  }
  // Which interior facets are constraints: looked up in parts (a random access into the map each,
  // most of the work at a million simplices), once per facet, from its lower-numbered simplex.
  std::vector<uint8_t> constrained(tri.neighbors.size(), 0);
  if (plc.num_simplices() > 0)  // (none: a convex hull's triangulation, every facet free)
    for_each_part(s, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t)
        for (int i = 0; i <= D; ++i) {
          const uint32_t nb = tri.neighbors[(D + 1) * t + i];
          if (nb == kNone || nb / (D + 1) < t) continue;
          if (constraints.find(facet_key<D>(tri.simplex(static_cast<uint32_t>(t)), i)) != TupleMap<D>::kAbsent)
            constrained[(D + 1) * t + i] = constrained[nb] = 1;
        }
    });
  // Components across unconstrained facets (breadth-first).
  std::vector<int32_t> component(s, -1);
  int32_t components = 0;
  std::vector<uint32_t> queue;
  for (uint32_t start = 0; start < s; ++start) {
    if (component[start] >= 0) continue;
    component[start] = components;
    queue.assign(1, start);
    while (!queue.empty()) {
      const uint32_t t = queue.back();
      queue.pop_back();
      for (int i = 0; i <= D; ++i) {
        const uint32_t nb = tri.neighbors[(D + 1) * t + i];
        if (nb == kNone || component[nb / (D + 1)] >= 0 || constrained[(D + 1) * t + i]) continue;
        component[nb / (D + 1)] = components;
        queue.push_back(nb / (D + 1));
      }
    }
    ++components;
  }
  // Seeds name the component of a simplex that contains them (closed).
  std::vector<int32_t> name(components, -1);
  int32_t next = 0;
  for (const auto& seed : plc.region_seeds) {
    next = std::max(next, seed.region + 1);
    for (uint32_t t = 0; t < s; ++t) {
      bool inside = true;
      for (int i = 0; i <= D && inside; ++i) {
        predicates::Coords<D + 1> c;
        for (int k = 0; k <= D; ++k) c[k] = tri.point(tri.simplex(t)[k]);
        c[i] = seed.point.data();
        inside = predicates::orient<D>(c) != predicates::Sign::Negative;
      }
      if (inside) {
        name[component[t]] = seed.region;
        break;
      }
    }
  }
  for (auto& n : name)
    if (n < 0) n = next++;
  tri.regions.resize(s);
  for (uint32_t t = 0; t < s; ++t) tri.regions[t] = name[component[t]];
}

template void assign_regions<2>(Triangulation<2>&, const Plc<2>&, unsigned);
template void assign_regions<3>(Triangulation<3>&, const Plc<3>&, unsigned);
template void assign_regions<4>(Triangulation<4>&, const Plc<4>&, unsigned);
template void assign_regions<5>(Triangulation<5>&, const Plc<5>&, unsigned);

}  // namespace sweepcdt::detail
