// Star-shaped polytopes for the tests of star_cdt() and vertex deletion (paper §5): the link of a
// vertex in a triangulation, and convex polytopes scaled radially about the origin.
#pragma once
#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <vector>

#include "sweepcdt/cdt.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::fixtures {

// The simplices of `tri` that hold vertex v.
template <int D>
std::vector<std::size_t> star_of(const Triangulation<D>& tri, uint32_t v) {
  std::vector<std::size_t> star;
  for (std::size_t t = 0; t < tri.num_simplices(); ++t)
    if (std::count(tri.simplex(t), tri.simplex(t) + D + 1, v)) star.push_back(t);
  return star;
}

// Is v inside the domain: does every facet through it have a simplex on both sides?
template <int D>
bool is_interior_vertex(const Triangulation<D>& tri, uint32_t v) {
  for (std::size_t t : star_of(tri, v))
    for (int i = 0; i <= D; ++i)
      if (tri.simplex(t)[i] != v && tri.neighbors[t * (D + 1) + i] == kNone) return false;
  return true;
}

// The boundary of v's star (its link) as a PLC notated so that v's side is the domain, the link's
// vertices renumbered in increasing order (so the perturbation order of §6 is kept).
template <int D>
Plc<D> link_polytope(const Triangulation<D>& tri, uint32_t v) {
  std::map<uint32_t, uint32_t> local;
  const auto star = star_of(tri, v);
  for (std::size_t t : star)
    for (int i = 0; i <= D; ++i)
      if (tri.simplex(t)[i] != v) local.emplace(tri.simplex(t)[i], 0);
  Plc<D> plc;
  for (auto& [global, id] : local) {
    id = static_cast<uint32_t>(plc.num_points());
    plc.points.insert(plc.points.end(), tri.point(global), tri.point(global) + D);
  }
  for (std::size_t t : star) {
    predicates::Coords<D + 1> c;
    int k = 0;
    for (int i = 0; i <= D; ++i)
      if (tri.simplex(t)[i] != v) {
        plc.simplices.push_back(local[tri.simplex(t)[i]]);
        c[k++] = tri.point(tri.simplex(t)[i]);
      }
    c[D] = tri.point(v);
    plc.exterior.push_back(predicates::orient<D>(c) == predicates::Sign::Positive ? ExteriorSide::Negative : ExteriorSide::Positive);
  }
  return plc;
}

// The boundary of the convex hull of random integer directions (the axis points included, so the
// origin is inside), each point then scaled by a random integer in [1, max_scale]: star-shaped
// from the origin. max_scale = 1 keeps it convex, with coplanar facets and ties.
template <int D>
Plc<D> radial_polytope(std::mt19937_64& rng, int count, int max_scale) {
  Plc<D> directions;
  for (int k = 0; k < D; ++k)
    for (double sign : {-1.0, 1.0}) {
      std::array<double, D> p{};
      p[k] = sign * 8;
      directions.points.insert(directions.points.end(), p.begin(), p.end());
    }
  std::uniform_int_distribution<int> coordinate(-8, 8);
  while (static_cast<int>(directions.num_points()) < count) {
    std::array<double, D> p;
    for (auto& x : p) x = coordinate(rng);
    bool fresh = std::any_of(p.begin(), p.end(), [](double x) { return x != 0; });
    for (std::size_t i = 0; fresh && i < directions.num_points(); ++i)
      fresh = !std::equal(p.begin(), p.end(), directions.point(static_cast<uint32_t>(i)));
    if (fresh) directions.points.insert(directions.points.end(), p.begin(), p.end());
  }
  // The polytope numbers its points, and draws their scales, in the order of the hull's simplices:
  // the sweep sphere's, whatever the default algorithm is, so that the seeds keep their polytopes.
  Options sphere;
  sphere.algorithm = Algorithm::SweepSphere;
  const Triangulation<D> hull = cdt(directions, sphere);
  Plc<D> plc;
  std::uniform_int_distribution<int> scale(1, max_scale);
  std::vector<uint32_t> used(directions.num_points(), kNone);
  for (std::size_t t = 0; t < hull.num_simplices(); ++t)
    for (int i = 0; i <= D; ++i) {
      if (hull.neighbors[t * (D + 1) + i] != kNone) continue;
      // The hull facet opposite vertex i, in the simplex's order: the simplex's inside is on the
      // side of vertex i, the sign (-1)^(D-i) of orient(facet, vertex i).
      for (int k = 0; k <= D; ++k) {
        if (k == i) continue;
        uint32_t& id = used[hull.simplex(t)[k]];
        if (id == kNone) {
          id = static_cast<uint32_t>(plc.num_points());
          const double s = scale(rng);
          for (int j = 0; j < D; ++j) plc.points.push_back(s * directions.point(hull.simplex(t)[k])[j]);
        }
        plc.simplices.push_back(id);
      }
      plc.exterior.push_back((D - i) % 2 == 0 ? ExteriorSide::Negative : ExteriorSide::Positive);
    }
  return plc;
}

}  // namespace sweepcdt::fixtures
