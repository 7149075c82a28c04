// Internal: the facets of a triangulation, grouped — the sorted list of (facet key, simplex, local
// index) that compute_neighbors() and validate() pair up. Sorting instead of hashing keeps it simple
// and deterministic: O(s log s).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
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

// A simplex's vertex ids in ascending order, with the local index each has in the simplex: the key
// of the facet opposite sorted position j is `ids` without entry j, so one sort per simplex gives
// all D + 1 facet keys (instead of one sort per facet).
template <int D>
struct SortedSimplex {
  std::array<uint32_t, D + 1> ids;
  std::array<uint32_t, D + 1> local;

  explicit SortedSimplex(const uint32_t* simplex) {
    for (int i = 0; i <= D; ++i) {
      int j = i;
      for (; j > 0 && ids[j - 1] > simplex[i]; --j) ids[j] = ids[j - 1], local[j] = local[j - 1];
      ids[j] = simplex[i], local[j] = static_cast<uint32_t>(i);
    }
  }
  // The smallest id of the facet opposite sorted position j: the bucket it is sorted into.
  uint32_t smallest_without(int j) const { return ids[j == 0 ? 1 : 0]; }
  FacetEntry<D> facet_without(int j, uint32_t simplex) const {
    FacetEntry<D> e;
    for (int i = 0, k = 0; i <= D; ++i)
      if (i != j) e.key[k++] = ids[i];
    e.simplex = simplex;
    e.local = local[j];
    return e;
  }
};

// An allocator that leaves new elements default-initialised: a facet list is written entry by entry
// right after it is made, so zeroing it first (as std::vector does) would be a wasted pass.
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <int D>
using FacetList = std::vector<FacetEntry<D>, DefaultInitAllocator<FacetEntry<D>>>;

// Counting sort by the smallest vertex id, then small sorts within each bucket: O(s) for meshes.
// The counting and the scattering run in parts of the simplices (each part its own counts, so its
// own slots in each bucket); the order within a bucket before its sort does not matter, as (key,
// simplex) orders the entries totally.
template <int D>
FacetList<D> sorted_facets(const Triangulation<D>& tri, unsigned threads = 1) {
  const std::size_t n = tri.num_points(), simplices = tri.num_simplices();
  // At most 8 parts: each holds a count per point.
  const unsigned scatter_threads = std::min(thread_count(threads), 8u);
  std::vector<std::vector<uint32_t>> next(parts_for(simplices, scatter_threads));
  for_each_part(simplices, scatter_threads, [&](std::size_t part, std::size_t begin, std::size_t end) {
    std::vector<uint32_t>& count = next[part];
    count.assign(n, 0);
    for (std::size_t t = begin; t < end; ++t) {
      const SortedSimplex<D> s(tri.simplex(static_cast<uint32_t>(t)));
      count[s.ids[0]] += D;  // every facet but the one without ids[0]
      ++count[s.ids[1]];
    }
  });
  // Bucket v holds [start[v], start[v + 1]); within it each part's entries follow the last part's.
  std::vector<uint32_t> start(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v) {
    uint32_t at = start[v];
    for (std::vector<uint32_t>& count : next) {
      const uint32_t c = count[v];
      count[v] = at;
      at += c;
    }
    start[v + 1] = at;
  }
  FacetList<D> facets(start[n]);
  for_each_part(simplices, scatter_threads, [&](std::size_t part, std::size_t begin, std::size_t end) {
    std::vector<uint32_t>& fill = next[part];
    for (std::size_t t = begin; t < end; ++t) {
      const SortedSimplex<D> s(tri.simplex(static_cast<uint32_t>(t)));
      for (int j = 0; j <= D; ++j) facets[fill[s.smallest_without(j)]++] = s.facet_without(j, static_cast<uint32_t>(t));
    }
  });
  // Within a bucket the first ids are equal: compare the rest, the second and third as one 64-bit
  // key, then element by element (std::array's operators go through memcmp, a call per comparison).
  const auto less = [](const FacetEntry<D>& a, const FacetEntry<D>& b) {
    if constexpr (D >= 3) {
      const uint64_t x = uint64_t{a.key[1]} << 32 | a.key[2], y = uint64_t{b.key[1]} << 32 | b.key[2];
      if (x != y) return x < y;
      for (int i = 3; i < D; ++i)
        if (a.key[i] != b.key[i]) return a.key[i] < b.key[i];
    } else {
      for (int i = 1; i < D; ++i)
        if (a.key[i] != b.key[i]) return a.key[i] < b.key[i];
    }
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
void for_each_facet_group(const FacetList<D>& facets, Group&& group) {
  for (std::size_t begin = 0; begin < facets.size();) {
    std::size_t end = begin + 1;
    while (end < facets.size() && same_tuple(facets[end].key, facets[begin].key)) ++end;
    group(begin, end);
    begin = end;
  }
}

}  // namespace sweepcdt::detail
