// One surface file through the mesh pipeline:
//   io::import_plc → cdt(plc, options, &triangulated) → [--check: validate_triangulated] →
//   io::volume_mesh_of → io::write_volume_mesh per output (atomic: nothing under the name unless complete).
#pragma once
#include <string>
#include <vector>

#include "file_result.h"
#include "progress.h"
#include "run_options.h"
#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::cli {

struct MeshTarget {
  std::string file;
  io::MeshFormat format;
};

// One CDT, written to every target (several formats at once cost one computation). If a write
// fails, the targets already written by this call are removed again: a file converts completely or
// leaves nothing. Never throws: every failure is in the result (code, message, details).
FileResult convert_surface(const std::string& input, const std::vector<MeshTarget>& targets, const RunOptions& options,
                           FileProgress& progress);

// The volume mesh of a CDT, with its boundary triangles and regions counted in `r`.
io::VolumeMesh counted_volume_mesh(Triangulation<3> tri, const Plc<3>& triangulated, FileResult& r);

// After writing `mesh` to the Abaqus file `file`: a warning in `r` if coordinates had to be rounded.
void warn_if_rounded(const std::string& file, const io::VolumeMesh& mesh, FileResult& r);

// "15706 tetrahedra, 0 Steiner points (sweep-sphere, 0.53 s)"
std::string summary_of(const FileResult& r);

}  // namespace sweepcdt::cli
