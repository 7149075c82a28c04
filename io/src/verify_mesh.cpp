#include "sweepcdt/io/verify_mesh.h"

#include "sweepcdt/io/to_plc.h"

namespace sweepcdt::io {

MeshVerification verify_mesh(const Plc<3>& input, const VolumeMesh& mesh, FacetMode facets) {
  return verify_cdt(input, {mesh.points, mesh.tetrahedra, mesh.regions, mesh.boundary, mesh.boundary_tags}, facets);
}

MeshVerification verify_mesh_files(const std::filesystem::path& input, const std::filesystem::path& mesh, FacetMode facets, double snap) {
  const Plc<3> surface = import_plc(input, snap, nullptr, /*for_cdt=*/false);
  return verify_mesh(surface, read_volume_mesh(mesh), facets);
}

}  // namespace sweepcdt::io
