// Is a volume mesh file exactly the CDT of a surface file? What `sweepcdt check` runs, and what the
// Python module and the hosts call to verify a mesh.
//
// The proof itself is core's verify_cdt() (sweepcdt/verify_cdt.h: exact geometry over plain
// arrays, what is checked and why); this layer adapts the io types to it — an io::VolumeMesh as
// read_volume_mesh() reads it — and reads the two files.
#pragma once
#include <filesystem>

#include "sweepcdt/io/volume_mesh.h"
#include "sweepcdt/verify_cdt.h"

namespace sweepcdt::io {

// `input`: import_plc(INPUT) (with the --snap the mesh was made with); `mesh`: read_volume_mesh(OUTPUT)
// or volume_mesh_of(); `facets`: the FacetMode the mesh was made with. Its boundary triangles and
// their face ids, when it has them, are checked too. Exact; never throws for a wrong mesh.
MeshVerification verify_mesh(const Plc<3>& input, const VolumeMesh& mesh, FacetMode facets);

// The surface file and the mesh file (any format read_volume_mesh() reads), then verify_mesh().
// Throws InputError (naming the file) when either cannot be read, as import_plc and read_volume_mesh do.
MeshVerification verify_mesh_files(const std::filesystem::path& input, const std::filesystem::path& mesh, FacetMode facets,
                                   double snap = 0);

}  // namespace sweepcdt::io
