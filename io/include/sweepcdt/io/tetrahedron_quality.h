// Element quality of a volume mesh's tetrahedra, for display (the MeshLab filter colours its
// cut-away view by it). Rounded floating-point arithmetic: a measure, never a decision.
#pragma once
#include <cstdint>

#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::io {

// The radius ratio 3 r / R of tetrahedron `tet` (r: inscribed, R: circumscribed radius): 1 for the
// regular tetrahedron, towards 0 for slivers and needles, 0 for a flat one.
double radius_ratio(const VolumeMesh& mesh, uint32_t tet);

}  // namespace sweepcdt::io
