// Step 4 of cavity_cdt.h: the part of the domain not covered by kept simplices, as PLCs, one per
// cavity (a component of Cavity simplices across their facets). D = 2..5.
#pragma once
#include <cstdint>
#include <vector>

#include "../delaunay/delaunay.h"
#include "domain_sides.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::detail {

template <int D>
struct CavityPlc {
  Plc<D> plc;                    // facet-bounded; its points are `global`'s, in that order
  std::vector<uint32_t> global;  // per cavity point: its id in the whole PLC (increasing)
};

template <int D>
struct Cavities {
  std::vector<CavityPlc<D>> parts;
  // A convex hull domain whose cavities reach the hull: no parts. The CDT's hull facets there need
  // not be the Delaunay ones — a constraint's edge can lie in a hull facet's plane, or a constraint
  // can hide a coplanar hull point — so they cannot bound a cavity.
  bool reaches_hull = false;
};

// The constraints of each cavity, each once:
//   - every facet between an Inside simplex and one of the cavity's, notated with the Inside side
//     exterior (unless it is a constraint whose notation puts the cavity side outside the domain:
//     then the cavity does not reach it);
//   - every other constraint that is missing from `dt` (in the cavity of the simplex it disturbs
//     first: all it disturbs are connected) or is a facet of one of the cavity's simplices, with its
//     own notation.
// The points: those of these constraints, and points on no constraint of the PLC at all that are
// vertices of the cavity's simplices.
template <int D>
Cavities<D> cavity_plcs(const Plc<D>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& constraint_of_facet,
                        const std::vector<uint32_t>& missing, const std::vector<uint32_t>& first_disturbed,
                        const std::vector<Place>& place);

}  // namespace sweepcdt::detail
