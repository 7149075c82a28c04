// verify_cdt(): is a tetrahedral mesh exactly the CDT of a closed surface? The proof behind
// `sweepcdt check`, the Python module's sweepcdt.check_files and the hosts' "verify" options.
//
// It trusts nothing the mesh says beyond its points and tetrahedra (and checks the boundary
// triangles and face ids it lists, when it lists them): the input points come first, bit for bit;
// every further point is a Steiner point cdt() can make (sweepcdt/steiner_point.h); the
// tetrahedra's boundary tiles the input's facets; validate() passes against that surface. The
// steps, and why Steiner points need care, are in core/src/verify/verify_cdt.cpp.
//
// Why here: every decision is exact geometry (sweepcdt::predicates, the spatial index BoxTree), and
// the mesh comes in as plain arrays, so the core holds it; io::verify_mesh
// (sweepcdt/io/verify_mesh.h) adapts an io::VolumeMesh read from a file. Never throws for a wrong
// mesh — that is a problem in the result — and never prints.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sweepcdt/cdt.h"

namespace sweepcdt {

// A volume mesh as plain arrays (views: the caller keeps them alive during the call).
struct TetMeshView {
  std::span<const double> points;           // n x 3: the input's points first, then Steiner points
  std::span<const uint32_t> tetrahedra;     // t x 4 point ids
  std::span<const int32_t> regions;         // t region ids, or empty
  std::span<const uint32_t> boundary;       // b x 3: the boundary triangles the mesh lists, or empty
  std::span<const uint32_t> boundary_tags;  // b face ids (kNone: none), or empty

  std::size_t num_points() const { return points.size() / 3; }
  std::size_t num_tetrahedra() const { return tetrahedra.size() / 4; }
  std::size_t num_boundary() const { return boundary.size() / 3; }
};

struct MeshVerification {
  std::vector<std::string> problems;  // the first ones, one line each
  std::size_t total_problems = 0;
  // What was found (for the report):
  bool input_points_moved = false;      // some input vertex differs in the mesh
  std::size_t steiner_points = 0;
  std::size_t steiner_exactly_on = 0;   // Steiner points exactly in the plane of their facet
  std::size_t facets = 0;               // the input's facets under the FacetMode checked
  std::size_t boundary_triangles = 0;   // boundary facets of the tetrahedra
  bool file_boundary = false;           // the mesh lists boundary triangles (checked against those)
  bool file_tags = false;               // ... with tags (face ids; checked too)
  bool validated = false;               // validate() ran (all earlier checks passed)
  int perturbation_order = 0;           // the order validate() passed under (paper §6; 0 = vertex ids)
  // Checked as FacetMode::Triangles, the mesh's boundary is not the input's surface, but it is as
  // FacetMode::Coplanar: the mesh was likely made with --facets coplanar.
  bool suggest_coplanar = false;
  // Checked as FacetMode::Coplanar, the mesh fails, but it passes as FacetMode::Triangles: it was
  // likely made with --facets triangles (its face ids name input triangles).
  bool suggest_triangles = false;
  bool ok() const { return total_problems == 0; }
};

// `input`: the surface as io::import_plc reads it (triangles with exterior notations); `mesh`: the
// volume mesh; `facets`: the FacetMode the mesh was made with. Exact.
MeshVerification verify_cdt(const Plc<3>& input, const TetMeshView& mesh, FacetMode facets);

}  // namespace sweepcdt
