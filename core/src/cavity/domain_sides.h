// Step 3 of cavity_cdt.h: which kept Delaunay simplices lie in the domain (D = 2..5).
#pragma once
#include <cstdint>
#include <vector>

#include "../delaunay/delaunay.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::detail {

enum class Place : uint8_t {
  Inside,   // kept: in the domain, a simplex of the CDT
  Outside,  // kept out: not in the domain
  Cavity,   // disturbed, or kept but unreached by the flood fill: triangulated again by the cavity sweep
};

// Per simplex of `dt`, given which are disturbed and which facets are constraints (disturbed.h).
// A convex hull domain (no notations) holds every simplex. Otherwise the hull is outside, and a
// constraint facet places the simplex on each side by its notation (None: inside on both); the
// places spread across facets that are no constraint, between simplices that are not disturbed.
// Kept simplices the fill does not reach (enclosed by disturbed ones) join the cavities. Empty when
// two places meet in one simplex, which notations of a checked PLC never cause. On `threads`
// threads (parallel.h); the result does not depend on their number.
template <int D>
std::vector<Place> domain_sides(const Plc<D>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& constraint_of_facet,
                                const std::vector<uint8_t>& disturbed, unsigned threads);

// The place the notation of constraint c gives the side of c where point p lies (p off c's plane).
template <int D>
Place side_of_constraint(const Plc<D>& plc, uint32_t c, uint32_t p);

}  // namespace sweepcdt::detail
