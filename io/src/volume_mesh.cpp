// volume_mesh_of(), the format names, and write_volume_mesh() / read_volume_mesh(), which hand the
// work to one file per format (write_*.cpp, read_*_mesh.cpp).
#include "sweepcdt/io/volume_mesh.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "facet_keys.h"
#include "file_io.h"
#include "reader_util.h"
#include "volume_mesh_formats.h"

namespace sweepcdt::io {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

VolumeMesh volume_mesh_of(Triangulation<3> tri, const Plc<3>& triangulated) {
  VolumeMesh mesh;
  const std::size_t t = tri.num_simplices();
  // The domain boundary: facets with no tetrahedron on the other side. cdt() pairs neighbours; a
  // triangulation built by hand may come without them.
  if (tri.neighbors.size() != 4 * t) compute_neighbors(tri);
  const detail::TriangleKeys constraints(triangulated);
  for (std::size_t s = 0; s < t; ++s)
    for (int i = 0; i < 4; ++i) {
      if (tri.neighbors[4 * s + i] != kNone) continue;
      // Outward from the one tetrahedron inside: counterclockwise seen from outside the material,
      // whichever way the input triangle was notated.
      const auto f = detail::outward_facet(tri.simplex(s), i);
      mesh.boundary.insert(mesh.boundary.end(), f.begin(), f.end());
      mesh.boundary_tags.push_back(constraints.tag_of(f.data()));
    }
  tri.neighbors = {};
  mesh.num_input_points = tri.num_input_points;
  mesh.on_triangle.assign(tri.num_input_points, kNone);
  mesh.on_triangle.insert(mesh.on_triangle.end(), tri.steiner_on.begin(), tri.steiner_on.end());
  mesh.on_triangle.resize(tri.num_points(), kNone);  // a triangulation built by hand may not say
  // The rest is the triangulation's own (moved, when the caller hands it over: no second copy).
  mesh.points = std::move(tri.points);
  mesh.tetrahedra = std::move(tri.simplices);
  mesh.regions = tri.regions.size() == t ? std::move(tri.regions) : std::vector<int32_t>(t, 0);
  return mesh;
}

const char* to_string(MeshFormat format) {
  switch (format) {
    case MeshFormat::Medit: return "mesh";
    case MeshFormat::Vtu: return "vtu";
    case MeshFormat::Gmsh41: return "msh";
    case MeshFormat::Gmsh22: return "msh22";
    case MeshFormat::TetGen: return "tetgen";
    case MeshFormat::Abaqus: return "inp";
  }
  return "unknown";
}

std::optional<MeshFormat> mesh_format_named(const std::string& word) {
  const std::string w = lower(word);
  if (w == "mesh" || w == "medit") return MeshFormat::Medit;
  if (w == "vtu") return MeshFormat::Vtu;
  if (w == "msh" || w == "msh41") return MeshFormat::Gmsh41;
  if (w == "msh22") return MeshFormat::Gmsh22;
  if (w == "tetgen" || w == "node" || w == "ele") return MeshFormat::TetGen;
  if (w == "inp" || w == "abaqus" || w == "calculix") return MeshFormat::Abaqus;
  return std::nullopt;
}

std::optional<MeshFormat> mesh_format_of(const std::filesystem::path& file) {
  const std::string ext = lower(file.extension().string());
  if (ext == ".mesh") return MeshFormat::Medit;
  if (ext == ".vtu") return MeshFormat::Vtu;
  if (ext == ".msh") return MeshFormat::Gmsh41;
  if (ext == ".node" || ext == ".ele" || ext == ".face") return MeshFormat::TetGen;
  if (ext == ".inp") return MeshFormat::Abaqus;
  return std::nullopt;
}

namespace detail {

TetGenNames tetgen_names(const std::filesystem::path& file) {
  const std::string ext = lower(file.extension().string());
  std::filesystem::path stem = file;
  if (ext == ".node" || ext == ".ele" || ext == ".face") stem.replace_extension();
  return {stem.string() + ".node", stem.string() + ".ele", stem.string() + ".face"};
}

}  // namespace detail

std::vector<std::filesystem::path> volume_mesh_files(const std::filesystem::path& file, MeshFormat format) {
  if (format != MeshFormat::TetGen) return {file};
  const auto names = detail::tetgen_names(file);
  return {names.node, names.ele, names.face};
}

namespace detail {

void check_writable(const VolumeMesh& m, const std::string& file) {
  auto refuse = [&](const std::string& why) { fail(InputErrorKind::Unsupported, file, Location::none(), "cannot write this mesh: " + why); };
  if (m.points.size() % 3 || m.tetrahedra.size() % 4 || m.boundary.size() % 3) refuse("an array's size is not a multiple of its width");
  if (m.regions.size() != m.num_tetrahedra()) refuse("regions and tetrahedra differ in number");
  if (m.boundary_tags.size() != m.num_boundary()) refuse("boundary_tags and boundary triangles differ in number");
  if (m.num_points() >= kNone) refuse("more than 2^32 - 2 points");
  if (m.num_input_points > m.num_points()) refuse("num_input_points exceeds the number of points");
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (!std::isfinite(m.points[i])) refuse("point " + std::to_string(i / 3) + " has a NaN or infinite coordinate");
  for (uint32_t id : m.tetrahedra)
    if (id >= m.num_points()) refuse("a tetrahedron names point " + std::to_string(id) + ", which does not exist");
  for (uint32_t id : m.boundary)
    if (id >= m.num_points()) refuse("a boundary triangle names point " + std::to_string(id) + ", which does not exist");
  for (uint32_t g : m.boundary_tags)  // Gmsh entity tags are ints: tag + 1 must fit, below its "untagged" entity
    if (g != kNone && g >= uint32_t{INT32_MAX} - 1) refuse("boundary tag " + std::to_string(g) + " (must be below 2^31 - 2)");
  for (int32_t r : m.regions)
    if (r < 0 || r == INT32_MAX) refuse("region id " + std::to_string(r) + " (must be 0 .. 2^31 - 2)");
}

void check_read(const VolumeMesh& m, const std::string& file) {
  const std::size_t n = m.num_points();
  for (std::size_t i = 0; i < m.tetrahedra.size(); ++i)
    if (m.tetrahedra[i] >= n)
      fail(InputErrorKind::IndexOutOfRange, file, Location::of("tetrahedron", i / 4),
           "names point " + std::to_string(m.tetrahedra[i]) + " (0-based) of " + std::to_string(n));
  for (std::size_t i = 0; i < m.boundary.size(); ++i)
    if (m.boundary[i] >= n)
      fail(InputErrorKind::IndexOutOfRange, file, Location::of("boundary triangle", i / 3),
           "names point " + std::to_string(m.boundary[i]) + " (0-based) of " + std::to_string(n));
}

}  // namespace detail

void write_volume_mesh(const std::filesystem::path& file, const VolumeMesh& mesh, MeshFormat format) {
  detail::check_writable(mesh, file.string());
  using detail::TextOut;
  std::vector<std::pair<std::filesystem::path, detail::TextMaker>> files;
  const auto one = [&](void (*writer)(const VolumeMesh&, TextOut&)) { return [&mesh, writer](TextOut& out) { writer(mesh, out); }; };
  switch (format) {
    case MeshFormat::Medit: files.emplace_back(file, one(detail::medit_text)); break;
    case MeshFormat::Vtu: files.emplace_back(file, one(detail::vtu_text)); break;
    case MeshFormat::Gmsh41: files.emplace_back(file, [&mesh](TextOut& out) { detail::gmsh_text(mesh, false, out); }); break;
    case MeshFormat::Gmsh22: files.emplace_back(file, [&mesh](TextOut& out) { detail::gmsh_text(mesh, true, out); }); break;
    case MeshFormat::Abaqus: files.emplace_back(file, one(detail::abaqus_text)); break;
    case MeshFormat::TetGen: {
      const auto names = detail::tetgen_names(file);
      files.emplace_back(names.node, one(detail::tetgen_node_text));
      files.emplace_back(names.ele, one(detail::tetgen_ele_text));
      files.emplace_back(names.face, one(detail::tetgen_face_text));
      break;
    }
  }
  detail::write_files_atomically(files, file.string());
}

VolumeMesh read_volume_mesh(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::optional<MeshFormat> format = mesh_format_of(file);
  std::error_code ec;
  if (!format && !std::filesystem::exists(file, ec) && std::filesystem::exists(file.string() + ".ele", ec)) format = MeshFormat::TetGen;
  if (format == MeshFormat::TetGen) {
    const auto names = detail::tetgen_names(file);
    VolumeMesh mesh = detail::read_tetgen(names.node, names.ele, names.face);
    detail::check_read(mesh, name);
    return mesh;
  }
  const std::string bytes = detail::read_file_bytes(file);
  // The content decides (the extension only says which format was meant).
  const std::size_t start = bytes.find_first_not_of(" \t\r\n");
  const std::string_view head = std::string_view(bytes).substr(start == std::string::npos ? bytes.size() : start, 64);
  VolumeMesh mesh;
  if (head.starts_with("MeshVersionFormatted")) mesh = detail::read_medit(bytes, name);
  else if (head.starts_with("<?xml") || head.starts_with("<VTKFile")) mesh = detail::read_vtu(bytes, name);
  else if (head.starts_with("$MeshFormat")) mesh = detail::read_gmsh(bytes, name);
  else if (head.starts_with("*")) mesh = detail::read_abaqus(bytes, name);
  else if (bytes.empty()) detail::fail(InputErrorKind::Truncated, name, Location::none(), "the file is empty");
  else
    detail::fail(InputErrorKind::UnknownFormat, name, Location::none(),
                 "not a volume mesh this reader knows (Medit .mesh, VTK .vtu, Gmsh .msh 2.2/4.1, Abaqus .inp, TetGen .node/.ele)");
  detail::check_read(mesh, name);
  return mesh;
}

}  // namespace sweepcdt::io
