// Step 3 of cavity_cdt.h: which kept Delaunay tetrahedra lie in the domain.
#pragma once
#include <cstdint>
#include <vector>

#include "../steiner/delaunay3.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::detail {

enum class Place : uint8_t {
  Inside,   // kept: in the domain, a tetrahedron of the CDT
  Outside,  // kept out: not in the domain
  Cavity,   // disturbed, or kept but unreached by the flood fill: triangulated again by the cavity sweep
};

// Per tetrahedron of `dt`, given which are disturbed and which facets are constraints (disturbed.h).
// A convex hull domain (no notations) holds every tetrahedron. Otherwise the hull is outside, and a
// constraint facet places the tetrahedron on each side by its notation (None: inside on both); the
// places spread across facets that are no constraint, between tetrahedra that are not disturbed.
// Kept tetrahedra the fill does not reach (enclosed by disturbed ones) join the cavities. Empty when
// two places meet in one tetrahedron, which notations of a checked PLC never cause. On `threads`
// threads (parallel.h); the result does not depend on their number.
std::vector<Place> domain_sides(const Plc<3>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& constraint_of_facet,
                                const std::vector<uint8_t>& disturbed, unsigned threads);

// The place the notation of constraint c gives the side of c where point p lies (p off c's plane).
Place side_of_constraint(const Plc<3>& plc, uint32_t c, uint32_t p);

}  // namespace sweepcdt::detail
