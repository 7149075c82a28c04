// Internal: the facets of a triangulation, grouped — the sorted list of (facet key, simplex, local
// index) that compute_neighbors() and validate() pair up. Sorting instead of hashing keeps it simple
// and deterministic: O(s log s).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "facet_hash.h"
#include "parallel.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {

template <int D>
using FacetKey = std::array<uint32_t, D>;  // sorted vertex ids

template <int D>
struct FacetEntry {
  FacetKey<D> key;
  uint32_t simplex;
  uint32_t local;  // the facet is opposite this local vertex
};

template <int D>
FacetKey<D> facet_key(const uint32_t* simplex, int opposite) {
  FacetKey<D> key;
  for (int i = 0, k = 0; i <= D; ++i)
    if (i != opposite) key[k++] = simplex[i];
  sort_tuple(key);
  return key;
}

// Counting sort by the smallest vertex id, then small sorts within each bucket: O(s) for meshes.
template <int D>
std::vector<FacetEntry<D>> sorted_facets(const Triangulation<D>& tri, unsigned threads = 1) {
  const std::size_t n = tri.num_points();
  std::vector<uint32_t> start(n + 1, 0);
  for (uint32_t t = 0; t < tri.num_simplices(); ++t)
    for (int i = 0; i <= D; ++i) ++start[facet_key<D>(tri.simplex(t), i)[0] + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<FacetEntry<D>> facets(start[n]);
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (uint32_t t = 0; t < tri.num_simplices(); ++t)
    for (int i = 0; i <= D; ++i) {
      const FacetKey<D> key = facet_key<D>(tri.simplex(t), i);
      facets[fill[key[0]]++] = {key, t, static_cast<uint32_t>(i)};
    }
  // Element by element (std::array's operators go through memcmp, a call per comparison here).
  const auto less = [](const FacetEntry<D>& a, const FacetEntry<D>& b) {
    for (int i = 0; i < D; ++i)
      if (a.key[i] != b.key[i]) return a.key[i] < b.key[i];
    return a.simplex < b.simplex;
  };
  // The buckets (one per smallest vertex) sort on their own: in parts of the vertices (parallel.h).
  for_each_part(n, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) std::sort(facets.begin() + start[v], facets.begin() + start[v + 1], less);
  });
  return facets;
}

// Calls group(begin, end) for each run of equal keys in sorted facets.
template <int D, class Group>
void for_each_facet_group(const std::vector<FacetEntry<D>>& facets, Group&& group) {
  for (std::size_t begin = 0; begin < facets.size();) {
    std::size_t end = begin + 1;
    while (end < facets.size() && same_tuple(facets[end].key, facets[begin].key)) ++end;
    group(begin, end);
    begin = end;
  }
}

}  // namespace sweepcdt::detail
