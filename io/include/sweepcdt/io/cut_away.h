// A cut-away view of a volume mesh, for hosts that show surfaces only (the MeshLab filter): the
// tetrahedra on one side of an axis-aligned plane, as the triangles that bound them. Inside the
// domain those are facets between a kept and a removed tetrahedron, so the cut shows the interior
// elements; the rest are the domain's own boundary triangles behind the plane.
#pragma once
#include <cstdint>
#include <vector>

#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::io {

struct CutAway {
  double position = 0;               // where the plane cut: coordinate along the axis
  uint32_t kept_tetrahedra = 0;
  std::vector<uint32_t> triangles;   // m x 3 ids of VolumeMesh::points, counterclockwise seen from
                                     // outside the kept tetrahedra
  std::vector<uint32_t> tetrahedron; // m: the kept tetrahedron each triangle bounds
  std::vector<uint8_t> on_cut;       // m: 1 for a facet shared with a removed tetrahedron, 0 for a
                                     // triangle of the domain boundary

  std::size_t num_triangles() const { return triangles.size() / 3; }
};

// Keeps the tetrahedra whose centroid lies at or below the plane `axis` (0, 1, 2 = x, y, z) =
// lo + fraction × (hi − lo), lo and hi the extent of the mesh points along the axis (fraction in
// [0, 1]; 1 keeps every tetrahedron, so the triangles are the domain boundary). The centroid test is
// rounded floating-point arithmetic: a display choice, not geometry that anything else relies on.
CutAway cut_away(const VolumeMesh& mesh, int axis, double fraction);

}  // namespace sweepcdt::io
