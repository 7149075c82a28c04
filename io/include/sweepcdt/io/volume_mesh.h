// Volume meshes out of sweepcdt: the tetrahedra of a cdt() result with what solvers and viewers need
// beside them (region ids, the boundary triangles with the input triangle each came from), and the
// writers/readers of the volume-mesh formats.
//
//   Plc<3> (import_plc) ──cdt(plc, options, &triangulated)──► Triangulation<3>
//        ──volume_mesh_of(tri, triangulated)──► VolumeMesh ──write_volume_mesh()──► .mesh .vtu .msh .node/.ele/.face .inp
//
// Every writer writes to a temporary file in the target folder and renames it at the end, so a failure
// never leaves a partial file under the requested name (the file there before, if any, stays).
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::io {

struct VolumeMesh {
  std::vector<double> points;        // n x 3: the input points first (same ids as the input), then Steiner points
  uint32_t num_input_points = 0;
  std::vector<uint32_t> tetrahedra;  // t x 4 point ids, each with positive volume: orient3d(a, b, c, d) > 0
                                     // in sweepcdt's convention (see core/predicates/orientation.h)
  std::vector<int32_t> regions;      // t region ids (1-based in files; as cdt() numbered them)
  std::vector<uint32_t> boundary;    // b x 3 point ids: the triangles of the domain boundary, ordered
                                     // counterclockwise seen from outside the material
  std::vector<uint32_t> boundary_tags;  // b: the input triangle each boundary triangle lies on (Plc::tags)
  std::vector<uint32_t> on_triangle;    // n, or empty when unknown: kNone for an input vertex; for a
                                        // Steiner point the input triangle it lies on (its index in
                                        // the PLC, Triangulation::steiner_on; for surfaces also its tag)

  std::size_t num_points() const { return points.size() / 3; }
  std::size_t num_tetrahedra() const { return tetrahedra.size() / 4; }
  std::size_t num_boundary() const { return boundary.size() / 3; }
};

// `triangulated` is the PLC cdt() actually triangulated (with Steiner points and split triangles).
// A triangulation handed over (std::move) becomes the mesh's arrays: a large mesh is not held twice
// while it is written (the fine perforated tube's 9M tetrahedra: 334 MB).
VolumeMesh volume_mesh_of(Triangulation<3> tri, const Plc<3>& triangulated);

enum class MeshFormat : uint8_t {
  Medit,    // .mesh
  Vtu,      // .vtu (VTK XML unstructured grid)
  Gmsh41,   // .msh (default version)
  Gmsh22,   // .msh with --format msh22
  TetGen,   // .node/.ele/.face (the name given may end in any of the three, or have no extension)
  Abaqus,   // .inp (Abaqus / CalculiX)
};

const char* to_string(MeshFormat format);  // "mesh", "vtu", "msh", "msh22", "tetgen", "inp"
// From a --format word (the to_string names; also "msh41", "node", "ele", "medit", "abaqus",
// "calculix"; any case) or nullopt.
std::optional<MeshFormat> mesh_format_named(const std::string& word);
// From the file name's extension, or nullopt.
std::optional<MeshFormat> mesh_format_of(const std::filesystem::path& file);

// The files write_volume_mesh(file, ..., format) writes: `file`, or TetGen's three beside each other.
std::vector<std::filesystem::path> volume_mesh_files(const std::filesystem::path& file, MeshFormat format);

// Throws InputError (kind Unreadable, naming the file) if it cannot be written; nothing is left behind.
void write_volume_mesh(const std::filesystem::path& file, const VolumeMesh& mesh, MeshFormat format);

// Reads a volume mesh written in any of the formats above (for `sweepcdt check`). Throws InputError.
VolumeMesh read_volume_mesh(const std::filesystem::path& file);

}  // namespace sweepcdt::io
