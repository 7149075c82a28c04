// The exact check that a star sweep's simplices are the CDT of the cavity a vertex deletion leaves
// (paper §5; EditableCdt::work_out) — validate()'s verdict for that one kind of PLC, in one pass over
// a few dozen facets instead of validate()'s general machinery, which was 16% of the deletions
// on Steiner-heavy parts (oblique_cylinders_fine: 30k deletions of ~20-simplex stars).
//
// The cavity: a facet-bounded PLC whose notated constraints (the link faces, and the facets through v
// that the star lies on one side of) bound a polytope, and whose unnotated constraints (the new facet
// pieces, or "sheets", with the star on both sides) lie inside it; no Steiner point subdivides
// anything. The checks, each exact:
//   1. every simplex has D + 1 distinct vertices of the cavity and is positively oriented;
//   2. every facet of the simplices is shared by one or two of them; two lie on opposite sides of it
//      (by the permutation between their vertex orders: both are positive, so no predicate);
//   3. a facet of one simplex is a notated constraint with the simplex on its domain side; a facet
//      of two is no notated constraint (a simplex would lie on its exterior side);
//   4. every constraint of the cavity is a facet of the simplices;
//   5. every facet of two simplices that is no constraint is locally Delaunay under the perturbation
//      of paper §6 (the cavity's points are numbered in perturbation order).
// Why 1–4 make the simplices a triangulation of the polytope (validate()'s domain and volume checks):
// count the simplices holding a generic point x. By 2 the count does not change across a facet of two
// simplices; by 3 and 4 the facets of one simplex are exactly the notated constraints, and crossing
// one into its domain side adds one. So the count is the winding number of the notated boundary about
// x, 1 inside the star-shaped polytope and 0 outside: the simplices tile it, meeting in whole facets.
// With 4 and 5 that is the CDT (paper §1: constrained, and locally Delaunay at every unconstrained
// facet). A vertex of the cavity that no simplex uses cannot occur: every one lies on a link face (4).
#pragma once
#include <string>

#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {

// Empty when `fill` is the CDT of `cavity` (as above), else what failed, as "check: detail" in
// validate()'s words. Sets fill.neighbors, as compute_neighbors() does.
template <int D>
std::string check_star_fill(Triangulation<D>& fill, const Plc<D>& cavity);

}  // namespace sweepcdt::detail
