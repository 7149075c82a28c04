#include "verify_facet_patches.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "../ids_text.h"
#include "../triangle_normal.h"
#include "sweepcdt/predicates.h"

namespace sweepcdt::detail {
namespace {

using predicates::Sign;

// An edge of a facet's pieces or of its boundary: lo < hi, `up` when it runs from lo to hi.
struct DirectedEdge {
  uint32_t facet, lo, hi;
  bool up;
  bool operator<(const DirectedEdge& o) const { return std::tie(facet, lo, hi) < std::tie(o.facet, o.lo, o.hi); }
  bool same_edge(const DirectedEdge& o) const { return facet == o.facet && lo == o.lo && hi == o.hi; }
};

DirectedEdge directed(uint32_t facet, uint32_t from, uint32_t to) { return {facet, std::min(from, to), std::max(from, to), from < to}; }

// A facet's projection: the axis dropped, and the sign there of its first triangle turned material
// side positive (all of a facet's triangles, so turned, have it: they are coplanar and agree).
struct Projection {
  int drop;
  Sign sign;
};

Projection projection_of(const Plc<3>& input, const SurfaceFacets& facets, uint32_t f) {
  const auto t = material_positive(input, facets.first_triangle(f));
  const predicates::Coords<3> abc{input.point(t[0]), input.point(t[1]), input.point(t[2])};
  int drop = dominant_axis(abc[0], abc[1], abc[2]);
  for (int tries = 0; tries < 3; ++tries, drop = (drop + 1) % 3) {
    const Sign sign = predicates::orient_projected<3>(abc, drop);
    if (sign != Sign::Zero) return {drop, sign};
  }
  return {drop, Sign::Zero};  // a degenerate input triangle (the importer rejects them): every piece fails
}

// The facet's boundary: its triangles' ridges, turned material side positive, split at their points.
void append_boundary(const Plc<3>& input, const SurfaceFacets& facets, const SurfacePoints& on, uint32_t f, std::vector<DirectedEdge>& out) {
  for (uint32_t j : facets.triangles[f]) {
    const auto t = material_positive(input, j);
    for (int k = 0; k < 3; ++k) {
      const uint32_t from = t[k], to = t[(k + 1) % 3];
      for (uint32_t e : facets.edges_of[j]) {
        const SurfaceFacets::Edge& edge = facets.edges[e];
        if (!edge.ridge || std::minmax(from, to) != std::minmax(edge.a, edge.b)) continue;
        const auto& line = on.on_edge[e];  // from edge.a to edge.b
        for (std::size_t i = 0; i + 1 < line.size(); ++i)
          out.push_back(from == edge.a ? directed(f, line[i], line[i + 1]) : directed(f, line[i + 1], line[i]));
      }
    }
  }
}

std::string edge_text(uint32_t from, uint32_t to) {
  const uint32_t ids[2] = {from, to};
  return ids_text(ids, 2);
}

// The pieces' edges against the facets' boundaries, both sorted.
void compare_edges(const Plc<3>& input, const SurfaceFacets& facets, const std::vector<DirectedEdge>& pieces,
                   const std::vector<DirectedEdge>& boundary, Problems& problems) {
  std::size_t p = 0, b = 0;
  while (p < pieces.size() || b < boundary.size()) {
    const DirectedEdge key = b == boundary.size() || (p < pieces.size() && pieces[p] < boundary[b]) ? pieces[p] : boundary[b];
    std::size_t up = 0, down = 0;
    for (; p < pieces.size() && pieces[p].same_edge(key); ++p) (pieces[p].up ? up : down) += 1;
    std::size_t boundary_up = 0, boundary_down = 0;
    for (; b < boundary.size() && boundary[b].same_edge(key); ++b) (boundary[b].up ? boundary_up : boundary_down) += 1;
    const bool on_boundary = boundary_up + boundary_down > 0;
    // The facet's boundary: once, in its direction. Inside the facet: once each way.
    if (on_boundary ? up == boundary_up && down == boundary_down : up == 1 && down == 1) continue;
    const std::string facet = facets.name(key.facet, input);
    if (on_boundary) {
      const std::string edge = boundary_up ? edge_text(key.lo, key.hi) : edge_text(key.hi, key.lo);
      const std::size_t along = boundary_up ? up : down, against = boundary_up ? down : up;
      if (along + against == 0) problems.add("edge " + edge + " of the boundary of " + facet + " is an edge of none of its boundary triangles");
      else
        problems.add("edge " + edge + " of the boundary of " + facet + " is an edge of " + std::to_string(along) + " of its boundary triangles in its direction and " +
                     std::to_string(against) + " against it (1 and 0 expected)");
    } else if (up + down == 1) {
      problems.add("edge " + edge_text(key.lo, key.hi) + " of the boundary triangles on " + facet +
                   " bounds their patch but is no piece of the facet's boundary");
    } else {
      problems.add("edge " + edge_text(key.lo, key.hi) + " inside " + facet + " is an edge of " + std::to_string(up) + " of its boundary triangles one way and " +
                   std::to_string(down) + " the other (1 and 1 expected)");
    }
  }
}

}  // namespace

std::vector<uint32_t> verify_facet_patches(const Plc<3>& input, const SurfaceFacets& facets, const SurfacePoints& on,
                                           std::span<const double> points, const std::vector<Triangle>& boundary, Problems& problems) {
  const auto p = [&](uint32_t v) { return points.data() + 3 * std::size_t{v}; };
  const bool triangles = facets.mode == FacetMode::Triangles;
  std::vector<Projection> projection;
  for (uint32_t f = 0; f < facets.num_facets(); ++f) projection.push_back(projection_of(input, facets, f));

  std::vector<uint32_t> facet_of(boundary.size(), kNone);
  std::vector<DirectedEdge> piece_edges;
  std::vector<std::pair<uint32_t, uint32_t>> vertices;  // (facet, vertex of one of its pieces)
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const Triangle& t = boundary[i];
    std::vector<uint32_t> common = on.facets_of[t[0]];
    for (int k = 1; k < 3; ++k) {
      std::vector<uint32_t> next;
      std::set_intersection(common.begin(), common.end(), on.facets_of[t[k]].begin(), on.facets_of[t[k]].end(), std::back_inserter(next));
      common.swap(next);
    }
    if (common.empty()) {
      problems.add("boundary triangle " + ids_text(t.data(), 3) + " does not lie on " + (triangles ? "an input triangle" : "one facet of the input"));
      continue;
    }
    const uint32_t f = facet_of[i] = common.front();
    if (predicates::orient_projected<3>({p(t[0]), p(t[1]), p(t[2])}, projection[f].drop) != projection[f].sign)
      problems.add("boundary triangle " + ids_text(t.data(), 3) + " on " + facets.name(f, input) + " has its tetrahedron on the outside of the surface");
    for (int k = 0; k < 3; ++k) {
      piece_edges.push_back(directed(f, t[k], t[(k + 1) % 3]));
      vertices.emplace_back(f, t[k]);
    }
  }

  std::vector<DirectedEdge> boundary_edges;
  for (uint32_t f = 0; f < facets.num_facets(); ++f) append_boundary(input, facets, on, f, boundary_edges);
  std::sort(piece_edges.begin(), piece_edges.end());
  std::sort(boundary_edges.begin(), boundary_edges.end());
  compare_edges(input, facets, piece_edges, boundary_edges, problems);

  std::sort(vertices.begin(), vertices.end());
  for (uint32_t f = 0; f < facets.num_facets(); ++f)
    for (uint32_t v : on.on_facet[f])
      if (!std::binary_search(vertices.begin(), vertices.end(), std::make_pair(f, v)))
        problems.add((v < input.num_points() ? "input vertex " : "Steiner point ") + std::to_string(v) + " lies on " + facets.name(f, input) +
                     " but is a vertex of none of its boundary triangles");
  return facet_of;
}

}  // namespace sweepcdt::detail
