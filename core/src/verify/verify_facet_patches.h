// Internal: step 3 of verify_cdt() (verify_cdt.cpp): the boundary of the tetrahedra is the input
// surface, facet by facet (surface_facets.h), exactly.
//
// Each boundary triangle (a facet of one tetrahedron, oriented with the tetrahedron on its positive
// side) is a piece of the facet that all three of its vertices lie on (surface_points.h), and in a
// projection along that facet's normal it has the orientation of the facet's triangles turned
// material side positive: its tetrahedron is on the material side. Then each facet's pieces must
// tile it:
//   - an edge of its pieces inside the facet is an edge of exactly two of them, once each way;
//   - their other edges are exactly the facet's boundary: its ridges split at their points, in
//     order (surface_points.h), each once and in the direction of the facet's own triangles;
//   - every point on the facet is a vertex of a piece.
// As a 2-chain of the projection the pieces then have the facet's boundary as their boundary, so
// their winding number is 1 on the facet and 0 off it; all pieces being positively oriented, that
// number counts the pieces over a point: exactly one piece covers each point of the facet, none
// covers anything else. (The facet's boundary is the input polygon's up to the rounding of the
// Steiner points on it: bit-for-bit reproduction is as far as exactness reaches there.)
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "problems.h"
#include "surface_facets.h"
#include "surface_points.h"

namespace sweepcdt::detail {

using Triangle = std::array<uint32_t, 3>;

// `points`: the mesh's (n x 3). Returns, per boundary triangle, the facet it lies on (kNone if none).
std::vector<uint32_t> verify_facet_patches(const Plc<3>& input, const SurfaceFacets& facets, const SurfacePoints& on,
                                           std::span<const double> points, const std::vector<Triangle>& boundary, Problems& problems);

}  // namespace sweepcdt::detail
