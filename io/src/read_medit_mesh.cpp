// Medit .mesh (ascii) reader: Vertices, Tetrahedra, Triangles; sections without volume meaning
// (Edges, Corners, Ridges, Required*, Normals, Tangents) are read past; anything else is refused.
#include <map>

#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {
namespace {

// Sections read past, with the number of tokens per entry.
const std::map<std::string_view, int> kSkipped = {
    {"Edges", 3},   {"Corners", 1}, {"Ridges", 1}, {"RequiredVertices", 1}, {"RequiredEdges", 1}, {"RequiredTriangles", 1},
    {"Normals", 3}, {"Tangents", 3}, {"NormalAtVertices", 2}, {"TangentAtVertices", 2}};

}  // namespace

VolumeMesh read_medit(std::string_view bytes, const std::string& file) {
  TextScanner in(bytes, file, '#');
  VolumeMesh m;
  bool have_vertices = false;
  for (std::string_view key = in.next_token(); !key.empty() && key != "End"; key = in.next_token()) {
    if (key == "MeshVersionFormatted") {
      const int64_t v = in.to_integer(in.next_token(), "version");
      if (v < 1 || v > 3) in.fail(InputErrorKind::Unsupported, "MeshVersionFormatted " + std::to_string(v));
    } else if (key == "Dimension") {
      if (in.to_integer(in.next_token(), "dimension") != 3) in.fail(InputErrorKind::Unsupported, "only Dimension 3 meshes are volume meshes");
    } else if (key == "Vertices") {
      if (have_vertices) in.fail(InputErrorKind::Syntax, "a second Vertices section");
      have_vertices = true;
      const uint64_t n = read_count(in, "vertices", 8);
      if (n >= kNone) in.fail(InputErrorKind::AbsurdCount, "more than 2^32 - 2 vertices");
      m.points.reserve(3 * n);
      for (uint64_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) m.points.push_back(in.to_double(in.next_token(), "a coordinate"));
        m.on_triangle.push_back(triangle_from_file(in.to_integer(in.next_token(), "a vertex reference")));
      }
      m.num_input_points = static_cast<uint32_t>(n);
    } else if (key == "Tetrahedra" || key == "Triangles") {
      if (!have_vertices) in.fail(InputErrorKind::Syntax, std::string(key) + " before Vertices");
      const bool tets = key == "Tetrahedra";
      const int corners = tets ? 4 : 3;
      const uint64_t count = read_count(in, tets ? "tetrahedra" : "triangles", 2 * (corners + 1));
      auto& ids = tets ? m.tetrahedra : m.boundary;
      ids.reserve(ids.size() + corners * count);
      for (uint64_t e = 0; e < count; ++e) {
        uint32_t v[4];
        for (int k = 0; k < corners; ++k) v[k] = read_id(in, m.num_points(), 1, "vertex");
        const int64_t ref = in.to_integer(in.next_token(), "a reference");
        if (tets) {
          for (uint32_t id : file_order(v)) ids.push_back(id);
          m.regions.push_back(region_from_file(in, ref));
        } else {
          ids.insert(ids.end(), v, v + 3);
          if (ref < 0 || ref > INT64_C(0xFFFFFFFF)) in.fail(InputErrorKind::Syntax, "triangle reference " + std::to_string(ref));
          m.boundary_tags.push_back(tag_from_file(ref));
        }
      }
    } else if (const auto it = kSkipped.find(key); it != kSkipped.end()) {
      const uint64_t count = read_count(in, "entries", 2 * it->second);
      for (uint64_t e = 0; e < count * it->second; ++e) in.to_double(in.next_token(), "a number");
    } else {
      in.fail(InputErrorKind::Unsupported, "section '" + std::string(key.substr(0, 40)) + "' (a volume mesh of tetrahedra has Vertices, Tetrahedra, Triangles)");
    }
  }
  if (!have_vertices) fail(InputErrorKind::Truncated, file, Location::none(), "no Vertices section");
  return m;
}

}  // namespace sweepcdt::io::detail
