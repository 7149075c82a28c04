// Facets of a D = 3 PLC given by triangles, and the segments that bound them.
//
// FacetMode::Triangles: every triangle is a facet, every triangle edge a segment.
// FacetMode::Coplanar: two triangles sharing an edge (and no third triangle on it) are one facet when
// they are exactly coplanar and have the material on the same side; the triangles of a facet are
// re-oriented to agree with its first triangle (their exterior notation flipped along), and only the
// edges on facet boundaries are segments.
#pragma once
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "edge_set.h"
#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

inline uint64_t edge_key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t{a} << 32) | b;
}

// Each edge of `triangles` that is not a segment, with the triangle(s) on its sides ({t, kNone} while
// only one is known); `first_seen`, if given, gets the keys in triangle order (deterministic, unlike
// the map's iteration order).
using EdgeSides = std::unordered_map<uint64_t, std::array<uint32_t, 2>>;
inline EdgeSides interior_edge_sides(const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeSet& segments,
                                     std::vector<uint64_t>* first_seen = nullptr) {
  EdgeSides sides;
  sides.reserve(triangles.size() * 3 / 2);  // about as many edges: no rehashing as it fills
  for (uint32_t t = 0; t < triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const uint64_t key = edge_key(triangles[t][i], triangles[t][(i + 1) % 3]);
      if (segments.count(key)) continue;
      auto [it, fresh] = sides.try_emplace(key, std::array<uint32_t, 2>{t, kNone});
      if (!fresh) it->second[1] = t;
      else if (first_seen) first_seen->push_back(key);
    }
  return sides;
}

// The vertex of triangle t that is not on edge `key` (an edge of t).
inline uint32_t third_vertex(const std::array<uint32_t, 3>& t, uint64_t key) {
  const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
  for (uint32_t v : t)
    if (v != a && v != b) return v;
  return kNone;
}

struct FacetGroups {
  std::vector<std::array<uint32_t, 3>> triangles;  // the input's triangles, oriented as their facet
  std::vector<ExteriorSide> exterior;              // per triangle, after re-orientation
  std::vector<uint32_t> facet;                     // per triangle: its facet, numbered 0..num_facets-1
  std::vector<uint32_t> first_triangle;            // per facet: its smallest input triangle index
  EdgeSet segments;                                // edge_key of every segment
  std::size_t num_facets() const { return first_triangle.size(); }
};

FacetGroups group_facets(const Plc<3>& plc, FacetMode mode);

}  // namespace sweepcdt::detail
