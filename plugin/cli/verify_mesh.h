// Is a volume mesh the CDT of a closed surface? The work behind `sweepcdt check` (check_command.cpp
// prints it). What is checked, and why the Steiner points need care, is in verify_mesh.cpp.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "sweepcdt/cdt.h"
#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::cli {

struct MeshVerification {
  std::vector<std::string> problems;  // the first ones, one line each
  std::size_t total_problems = 0;
  // What was found (for the report):
  bool input_points_moved = false;      // some input vertex differs in the mesh
  std::size_t steiner_points = 0;
  std::size_t steiner_exactly_on = 0;   // Steiner points exactly in the plane of their facet
  std::size_t facets = 0;               // the input's facets under the --facets mode checked
  std::size_t boundary_triangles = 0;   // boundary facets of the tetrahedra
  bool file_boundary = false;           // the file lists boundary triangles (checked against those)
  bool file_tags = false;               // ... with tags (face ids; checked too)
  bool validated = false;               // validate() ran (all earlier checks passed)
  int perturbation_order = 0;           // the order validate() passed under (paper §6; 0 = vertex ids)
  // Checked as FacetMode::Triangles, the mesh's boundary is not the input's surface, but it is as
  // FacetMode::Coplanar: the mesh was likely made with --facets coplanar; the report says so.
  bool suggest_coplanar = false;
  bool ok() const { return total_problems == 0; }
};

// `input`: io::import_plc(INPUT); `mesh`: io::read_volume_mesh(OUTPUT); `facets`: the --facets mode
// the mesh was made with. Exact; never throws for a wrong mesh (that is a problem in the result).
MeshVerification verify_mesh(const Plc<3>& input, const io::VolumeMesh& mesh, FacetMode facets);

}  // namespace sweepcdt::cli
