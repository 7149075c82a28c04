// star_cdt(): the CDT of a star-shaped polytope (paper §5), in O(n_s log n_v) time.
//
//   Plc<3> polytope = ...;                   // its boundary: constraining simplices, exterior notated
//   Triangulation<3> tri = star_cdt(polytope, {0.5, 0.5, 0.5});  // a point that sees all the boundary
//
// The polytope's constraining simplices bound it (each notated with its exterior side; unnotated
// ones are facets inside it), and `centre` sees every point of its boundary — it may lie on the
// boundary, or on an inner facet. This is the sweep sphere run inward: simplices are built in
// decreasing power Psi_centre, no vertex has a drop face and there is no seed, so the time is
// O(n_s log n_v) instead of the general sweep's O(n_v n_s). Vertex deletion (editable_cdt.h) uses
// it with the deleted vertex as centre and the link of its star as the boundary.
//
// The result is validated like cdt()'s: if the polytope is not star-shaped from `centre`, or has no
// CDT, star_cdt() throws NoCdtError, never returns a wrong triangulation. Throws PlcError for an
// invalid PLC, CancelledError when options.progress says so. Perturbed by vertex id (paper §6).
#pragma once
#include <array>

#include "sweepcdt/cdt.h"

namespace sweepcdt {

template <int D>
Triangulation<D> star_cdt(const Plc<D>& polytope, const std::array<double, D>& centre, const Options& options = {});

}  // namespace sweepcdt
