#include "facet_groups.h"

#include <algorithm>
#include <numeric>

#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::detail {
namespace {

struct DirectedEdge {
  uint64_t key;
  uint32_t triangle;
  uint32_t from;  // the edge runs from -> to in the triangle's vertex order
};

ExteriorSide flipped(ExteriorSide side) {
  switch (side) {
    case ExteriorSide::Positive: return ExteriorSide::Negative;
    case ExteriorSide::Negative: return ExteriorSide::Positive;
    case ExteriorSide::None: return ExteriorSide::None;
  }
  return side;
}

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

FacetGroups group_facets(const Plc<3>& plc, FacetMode mode) {
  FacetGroups g;
  const std::size_t m = plc.num_simplices();
  g.triangles.resize(m);
  g.exterior.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    g.triangles[j] = {plc.simplex(j)[0], plc.simplex(j)[1], plc.simplex(j)[2]};
    g.exterior[j] = plc.exterior_of(j);
  }
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * m);
  for (uint32_t j = 0; j < m; ++j)
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = g.triangles[j][i], b = g.triangles[j][(i + 1) % 3];
      edges.push_back({edge_key(a, b), j, a});
    }
  std::sort(edges.begin(), edges.end(), [](const DirectedEdge& x, const DirectedEdge& y) {
    return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
  });

  // Merges: pairs of triangles across an edge of exactly two, coplanar, material on the same side.
  // `same_direction`: both traverse the edge the same way, so their orientations disagree.
  struct Merge {
    uint32_t s, t;
    bool same_direction;
  };
  std::vector<Merge> merges;
  std::vector<uint32_t> parent(m);
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::size_t begin = 0; begin < edges.size();) {
    std::size_t end = begin + 1;
    while (end < edges.size() && edges[end].key == edges[begin].key) ++end;
    bool merged = false;
    if (mode == FacetMode::Coplanar && end - begin == 2) {
      const DirectedEdge& e = edges[begin];
      const DirectedEdge& f = edges[begin + 1];
      const bool same_direction = e.from == f.from;
      const uint32_t d = third_vertex(g.triangles[f.triangle], f.key);
      const auto& t = g.triangles[e.triangle];
      const bool coplanar =
          predicates::orient<3>({plc.point(t[0]), plc.point(t[1]), plc.point(t[2]), plc.point(d)}) == predicates::Sign::Zero;
      const ExteriorSide other = same_direction ? flipped(g.exterior[f.triangle]) : g.exterior[f.triangle];
      if (coplanar && other == g.exterior[e.triangle]) {
        merges.push_back({e.triangle, f.triangle, same_direction});
        parent[find_root(parent, e.triangle)] = find_root(parent, f.triangle);
        merged = true;
      }
    }
    if (!merged) g.segments.insert(edges[begin].key);
    begin = end;
  }

  // Facet numbers in order of their first triangle.
  g.facet.assign(m, kNone);
  std::vector<uint32_t> facet_of_root(m, kNone);
  for (uint32_t j = 0; j < m; ++j) {
    uint32_t& f = facet_of_root[find_root(parent, j)];
    if (f == kNone) {
      f = static_cast<uint32_t>(g.first_triangle.size());
      g.first_triangle.push_back(j);
    }
    g.facet[j] = f;
  }
  if (merges.empty()) return g;

  // Re-orient each facet like its first triangle: walk the merge edges breadth-first from it.
  std::vector<std::vector<std::pair<uint32_t, bool>>> across(m);
  for (const Merge& mg : merges) {
    across[mg.s].push_back({mg.t, mg.same_direction});
    across[mg.t].push_back({mg.s, mg.same_direction});
  }
  std::vector<int8_t> reversed(m, -1);
  std::vector<uint32_t> queue;
  for (uint32_t first : g.first_triangle) {
    reversed[first] = 0;
    queue.assign(1, first);
    for (std::size_t q = 0; q < queue.size(); ++q)
      for (const auto& [next, same] : across[queue[q]])
        if (reversed[next] < 0) {
          reversed[next] = static_cast<int8_t>(reversed[queue[q]] ^ (same ? 1 : 0));
          queue.push_back(next);
        }
  }
  for (uint32_t j = 0; j < m; ++j)
    if (reversed[j] == 1) {
      std::swap(g.triangles[j][1], g.triangles[j][2]);
      g.exterior[j] = flipped(g.exterior[j]);
    }
  return g;
}

}  // namespace sweepcdt::detail
