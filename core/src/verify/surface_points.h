// Internal: step 2 of verify_cdt() (verify_cdt.cpp): where each vertex of the mesh lies on the input
// surface, exactly, without trusting the mesh. Input vertices lie on the facets of their triangles.
// Every further vertex (a Steiner point), in the order the mesh lists them, must be exactly a point
// that `--steiner auto` can make (sweepcdt/steiner_point.h: the rounded a + t (b - a) for some t in
// (0, 1), decided exactly) from two points already placed:
//   - on a ridge (surface_facets.h): a point of the ridge's segment, made from its two input ends;
//     the ridge's points are kept in order from end to end (rounding is monotone, so its points
//     are ordered alike in every coordinate); the point lies on every facet that has the ridge.
//     On a segment whose ends' difference rounds (and in meshes made before 2026-11-27), it is
//     made from the two neighbouring points on the ridge it falls between;
//   - a fold point: a point between any two points of one facet (core/src/steiner/refine.h:
//     rounding makes some edges inside a facet folds, which are split when not Delaunay); it lies
//     inside that facet. So do points on input edges inside a coplanar facet: a fold along one, or
//     a mesh made with --facets triangles checked as coplanar.
// Rounding is monotone, so a split point stays in the box of its two points: only the ridges and
// facets whose box holds it are tried. A facet's k points are not tried in pairs for a fold point
// (k²/2 exact tests, for each of the facet's fold points): split_of_two.h gives the same answer in
// O(k log k), tried first on the points nearest the fold point (surface_points.cpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "problems.h"
#include "surface_facets.h"

namespace sweepcdt::detail {

struct SurfacePoints {
  std::vector<std::vector<uint32_t>> on_edge;    // per input edge: its points from a to b (ridges; else a, b)
  std::vector<std::vector<uint32_t>> on_facet;   // per facet: the points on it, ascending
  std::vector<std::vector<uint32_t>> facets_of;  // per mesh point: the facets it lies on, ascending
  std::size_t exactly_on = 0;                    // Steiner points exactly in the plane of their first facet
  // Per facet: it holds a Steiner point that is not exactly on its ridge's segment, strictly inside
  // it (rounded off it, or a fold point), so its pieces may differ from it by rounding
  // (verify_cdt.cpp: only their pairs are tested for crossings, as refined_check.h does in cdt()).
  std::vector<char> off_facet;
};

// `points`: the mesh's (n x 3), the input's first (step 1). A Steiner point that is not reproduced
// is a problem, and lies on no facet.
SurfacePoints locate_points(const Plc<3>& input, const SurfaceFacets& facets, std::span<const double> points, Problems& problems);

}  // namespace sweepcdt::detail
