// Each facet's triangles made its 2D constrained Delaunay triangulation by Lawson's edge flips (paper
// §1: the constraining simplices of a facet are its own (d-1)-dimensional CDT; the 3D CDT, when it
// exists, contains exactly these triangles).
//
// The in-circle test of four coplanar points a, b, c, d is the 3D insphere test of a, b, c, e, d for
// any point e off their plane: the sphere through a, b, c, e meets the plane in the circumcircle of
// a, b, c. Under the lifting-map perturbation (§6) e is never the decisive vertex, because its
// cofactor is orient(a, b, c, d) = 0, so the 2D answer agrees with the 3D perturbation that the
// sweep uses. Rounded Steiner points make some facets coplanar only to within rounding; there the
// same test is a close approximation, and cdt() checks the result exactly anyway.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "edge_set.h"

namespace sweepcdt::detail {

struct FacetTriangles {
  const std::vector<double>& points;                 // n x 3
  std::vector<std::array<uint32_t, 3>>& triangles;   // oriented alike within each facet; two that share
                                                     // an edge that is not a segment are in one facet
  const EdgeSet& segments;                           // never flipped
  // Per point: the input segment (two input vertex ids, sorted) a Steiner point lies on, or
  // {kNone, kNone} for input points. A flip never joins two points of one segment.
  const std::vector<std::array<uint32_t, 2>>& on_segment;
};

// Flips every facet to its CDT; returns the number of flips.
uint64_t flip_facets_to_cdt(FacetTriangles facets);

// Folds (refine.h): two triangles of one facet that are not exactly coplanar, because a rounded
// Steiner point lies a few ulps off its segment, meet at a ridge of the refined PLC, which the CDT
// theorem needs Delaunay. Any triangulation of a facet will do, so a fold that is not an edge of the
// Delaunay triangulation is flipped to the other diagonal of its (strictly convex) quadrilateral
// when that one is: each flip trades a non-Delaunay edge for a Delaunay one, so the flips end.
// Returns the number of flips; `delaunay_edge(a, b)` says whether ab is a Delaunay edge. `bent`: per
// point, whether it may lie off the plane of a facet holding it (a rounded Steiner point); a
// quadrilateral of four others is flat, no fold, and is passed over without its predicates (the
// exact stage of an orientation that is zero, on every facet edge of the surface).
uint64_t flip_folds_to_delaunay(FacetTriangles facets, const std::vector<char>& bent,
                                const std::function<bool(uint32_t, uint32_t)>& delaunay_edge);

}  // namespace sweepcdt::detail
