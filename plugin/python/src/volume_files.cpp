#include "volume_files.h"

#include <cmath>
#include <set>
#include <utility>

#include "arrays.h"
#include "errors.h"
#include "sweepcdt/io/volume_mesh.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::python {
namespace {

// TetMesh and the files order tetrahedra (a, b, d, c) relative to io::VolumeMesh (volume_mesh_formats.h).
void swap_last_two(std::vector<uint32_t>& tets) {
  for (std::size_t t = 0; t + 3 < tets.size(); t += 4) std::swap(tets[t + 2], tets[t + 3]);
}

std::vector<uint32_t> ids32(const std::vector<int64_t>& ids, std::size_t limit, const char* what) {
  std::vector<uint32_t> out;
  out.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] < 0 || static_cast<uint64_t>(ids[i]) >= limit)
      throw py::value_error(std::string(what) + ": entry " + std::to_string(i) + " (" + std::to_string(ids[i]) +
                            ") is not in [0, " + std::to_string(limit) + ")");
    out.push_back(static_cast<uint32_t>(ids[i]));
  }
  return out;
}

}  // namespace

py::dict read_volume_mesh(const std::filesystem::path& file) {
  io::VolumeMesh m;
  {
    py::gil_scoped_release release;
    m = io::read_volume_mesh(file);
  }
  swap_last_two(m.tetrahedra);
  py::dict r;
  r["points"] = to_numpy<double>(m.points, 3);
  r["tetrahedra"] = to_numpy<int64_t>(m.tetrahedra, 4);
  r["regions"] = to_numpy<int32_t>(m.regions, 0);
  r["triangles"] = to_numpy<int64_t>(m.boundary, 3);
  r["triangle_ids"] = to_numpy<int64_t>(m.boundary_tags, 0);
  r["num_input_points"] = m.num_input_points;
  std::vector<int64_t> steiner;
  for (std::size_t i = m.num_input_points; i < m.num_points(); ++i)
    steiner.push_back(i < m.on_triangle.size() && m.on_triangle[i] != kNone ? static_cast<int64_t>(m.on_triangle[i]) : -1);
  r["steiner_triangles"] = to_numpy<int64_t>(steiner, 0);
  std::vector<int64_t> identity(m.num_points());
  for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<int64_t>(i);
  r["point_ids"] = to_numpy<int64_t>(identity, 0);
  py::dict s;
  s["points"] = m.num_points();
  s["tetrahedra"] = m.num_tetrahedra();
  s["boundary_triangles"] = m.num_boundary();
  s["steiner_points"] = m.num_points() - m.num_input_points;
  s["regions"] = std::set<int32_t>(m.regions.begin(), m.regions.end()).size();
  s["algorithm"] = "read";
  s["seconds_total"] = 0.0;
  r["stats"] = s;
  return r;
}

void write_volume_mesh(const std::filesystem::path& file, const py::handle& points, const py::handle& tetrahedra,
                       const py::handle& regions, const py::handle& triangles, const py::handle& triangle_ids,
                       const std::optional<std::string>& format) {
  std::optional<io::MeshFormat> f = format ? io::mesh_format_named(*format) : io::mesh_format_of(file);
  if (!f) throw py::value_error(file.string() + ": unknown volume-mesh format; use .mesh, .vtu, .msh, .node or .inp, or format=");
  io::VolumeMesh m;
  m.points = real_matrix(points, "points", 3);
  for (double x : m.points)
    if (!std::isfinite(x)) throw py::value_error("points: a coordinate is not finite");
  const std::size_t n = m.num_points();
  m.num_input_points = static_cast<uint32_t>(n);
  m.tetrahedra = ids32(index_matrix(tetrahedra, "tetrahedra", 4), n, "tetrahedra");
  swap_last_two(m.tetrahedra);
  const std::size_t t = m.num_tetrahedra();
  if (regions.is_none()) m.regions.assign(t, 0);
  else for (int64_t r : index_vector(regions, "regions", t)) {
    if (r < 0 || r > INT32_MAX - 1) throw py::value_error("regions: " + std::to_string(r) + " is not in [0, 2^31 - 1)");
    m.regions.push_back(static_cast<int32_t>(r));
  }
  if (!triangles.is_none()) {
    m.boundary = ids32(index_matrix(triangles, "triangles", 3), n, "triangles");
    const std::size_t b = m.num_boundary();
    if (triangle_ids.is_none()) m.boundary_tags.assign(b, 0);
    else m.boundary_tags = ids32(index_vector(triangle_ids, "triangle_ids", b), kNone, "triangle_ids");
  }
  py::gil_scoped_release release;
  try {
    io::write_volume_mesh(file, m, *f);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw OutputFailure(e.what());
  }
}

}  // namespace sweepcdt::python
