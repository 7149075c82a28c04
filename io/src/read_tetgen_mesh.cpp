// TetGen .node / .ele / .face reader. Point ids start at the first id of the .node file (0 or 1, as
// TetGen allows); .ele: 4 or 10 nodes per tetrahedron (corners first), the first attribute is the
// region (r + 1, as written); .face (optional: no .face, no boundary): the marker is the boundary tag
// + 1. Elements keep the order of the files.
#include <cmath>

#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {

namespace {

// The .node file: points and the id of the first (the base of every id in the other files).
int64_t read_nodes(const std::string& bytes, const std::string& name, VolumeMesh& m) {
  TextScanner in(bytes, name, '#');
  const uint64_t n = read_count(in, "points", 8);
  if (n >= kNone) in.fail(InputErrorKind::AbsurdCount, "more than 2^32 - 2 points");
  if (in.to_integer(in.next_token(), "dimension") != 3) in.fail(InputErrorKind::Unsupported, "only 3D .node files are volume meshes");
  const int64_t attributes = in.to_integer(in.next_token(), "number of attributes", 0, 1 << 20);
  const int64_t markers = in.to_integer(in.next_token(), "number of boundary markers", 0, 1);
  int64_t base = 0;
  m.points.reserve(3 * n);
  for (uint64_t i = 0; i < n; ++i) {
    const int64_t id = in.to_integer(in.next_token(), "a point id");
    if (i == 0) {
      if (id != 0 && id != 1) in.fail(InputErrorKind::Syntax, "the first point id must be 0 or 1, not " + std::to_string(id));
      base = id;
    } else if (id != base + static_cast<int64_t>(i)) {
      in.fail(InputErrorKind::Syntax, "point ids must be consecutive: expected " + std::to_string(base + static_cast<int64_t>(i)) + ", found " + std::to_string(id));
    }
    for (int k = 0; k < 3; ++k) m.points.push_back(in.to_double(in.next_token(), "a coordinate"));
    for (int64_t a = 0; a < attributes; ++a) in.to_double(in.next_token(), "an attribute");
    if (markers) m.on_triangle.push_back(triangle_from_file(in.to_integer(in.next_token(), "a boundary marker")));
  }
  m.num_input_points = static_cast<uint32_t>(n);
  return base;
}

}  // namespace

VolumeMesh read_tetgen(const std::filesystem::path& node, const std::filesystem::path& ele, const std::filesystem::path& face) {
  VolumeMesh m;
  const std::string node_name = node.string(), ele_name = ele.string(), face_name = face.string();
  const int64_t base = read_nodes(read_file_bytes(node), node_name, m);
  const uint64_t n = m.num_points();
  {
    const std::string bytes = read_file_bytes(ele);
    TextScanner in(bytes, ele_name, '#');
    const uint64_t t = read_count(in, "tetrahedra", 10);
    const int64_t corners = in.to_integer(in.next_token(), "nodes per tetrahedron");
    if (corners != 4 && corners != 10) in.fail(InputErrorKind::Unsupported, std::to_string(corners) + " nodes per tetrahedron (4 or 10)");
    const int64_t attributes = in.to_integer(in.next_token(), "number of attributes", 0, 1 << 20);
    m.tetrahedra.reserve(4 * t);
    m.regions.reserve(t);
    for (uint64_t e = 0; e < t; ++e) {
      in.to_integer(in.next_token(), "a tetrahedron id");
      uint32_t v[4];
      for (int k = 0; k < 4; ++k) v[k] = read_id(in, n, base, "point");
      for (int k = 4; k < corners; ++k) read_id(in, n, base, "point");
      int32_t region = 0;
      for (int64_t a = 0; a < attributes; ++a) {
        const double x = in.to_double(in.next_token(), "an attribute");
        if (a > 0) continue;
        if (!(x >= 0 && x <= INT32_MAX) || x != std::floor(x)) in.fail(InputErrorKind::Syntax, "the region attribute must be a whole number in [0, 2^31 - 1]");
        region = region_from_file(in, static_cast<int64_t>(x));
      }
      for (uint32_t id : file_order(v)) m.tetrahedra.push_back(id);
      m.regions.push_back(region);
    }
  }
  std::error_code ec;
  if (std::filesystem::exists(face, ec)) {
    const std::string bytes = read_file_bytes(face);
    TextScanner in(bytes, face_name, '#');
    const uint64_t b = read_count(in, "faces", 8);
    const int64_t markers = in.to_integer(in.next_token(), "number of boundary markers", 0, 1);
    m.boundary.reserve(3 * b);
    for (uint64_t f = 0; f < b; ++f) {
      in.to_integer(in.next_token(), "a face id");
      for (int k = 0; k < 3; ++k) m.boundary.push_back(read_id(in, n, base, "point"));
      const int64_t marker = markers ? in.to_integer(in.next_token(), "a boundary marker", 0, INT64_C(0xFFFFFFFF)) : 0;
      m.boundary_tags.push_back(tag_from_file(marker));
    }
  }
  return m;
}

}  // namespace sweepcdt::io::detail
