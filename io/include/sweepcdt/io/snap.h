// snap_coordinates(): the one place where sweepcdt moves input geometry, and only when asked
// (`sweepcdt --snap TOL`).
//
// CAD exporters write faces that are flat by design with rounding noise: gearwheel_ascii.stl's
// bottom face has z = 0 at most vertices and z = ±5e-17 at others. Exactly, that face is a field
// of slight folds, every one of its edges is a ridge, and its long thin triangles then need about
// one Steiner point per unit of 1/angle (core/src/steiner/refine.h) — far too many. TetGen merges
// such faces with a tolerance (-T); sweepcdt stays exact and instead offers this explicit repair:
// along each axis, coordinate values that lie within TOL × (bounding-box diagonal) of each other
// become one value, so the face is exactly flat and `--facets coplanar` merges it. Everything after
// it (welding, the surface checks, the CDT, validation) is exact again, on the snapped points.
#pragma once
#include <cstdint>

#include "sweepcdt/io/surface.h"

namespace sweepcdt::io {

// The largest tolerance any front end accepts (relative to the bounding-box diagonal): snapping
// repairs rounding noise, not modelling error. `sweepcdt --snap`, the Python module, MeshLab.
inline constexpr double kLargestSnap = 1e-3;

struct SnapReport {
  double tolerance = 0;            // absolute: relative tolerance × bounding-box diagonal
  uint64_t coordinates_moved = 0;  // of the welded points
  uint64_t points_moved = 0;       // welded points with a coordinate moved
  uint64_t points_merged = 0;      // welded points that became equal to another one
  uint64_t edges_flattened = 0;    // edges whose two triangles became exactly coplanar (were not):
                                   // what snapping did for --facets coplanar
  double largest_move = 0;
};

// The surface with its points snapped and welded again. Per axis, the distinct values of the
// points, in increasing order, are cut into clusters
// greedily: a cluster takes values while they are within the tolerance of its smallest one (so no
// value moves by more than the tolerance). Each cluster becomes its most frequent value (ties: the
// one of least magnitude, then the smaller): 0 for the noise above, and the bulk of a face stays.
// relative_tolerance must be finite and >= 0 (0 changes nothing). Points that become equal are
// welded (they keep the first one's id); triangles that become degenerate are left for inspect() to
// report. Triangle j stays input triangle j.
Surface snap_coordinates(const Surface& surface, double relative_tolerance, SnapReport& report);

}  // namespace sweepcdt::io
