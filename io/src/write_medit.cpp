// Medit .mesh (ascii, MeshVersionFormatted 2: double precision), as read by Medit, mmg, Gmsh, meshio.
//   Vertices     x y z ref                 (ref: 0 for an input vertex; for a Steiner point the
//                                            input triangle it lies on + 1)
//   Tetrahedra   a b c d region+1        (1-based point ids, positive volume)
//   Triangles    a b c tag+1             (boundary, counterclockwise seen from outside; 0 = no tag)
#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {

void medit_text(const VolumeMesh& m, TextOut& o) {
  std::string& out = o.text;
  out += "MeshVersionFormatted 2\nDimension 3\n\nVertices\n";
  append_int(out, static_cast<int64_t>(m.num_points()));
  out += '\n';
  for (std::size_t i = 0; i < m.num_points(); ++i) {
    append_point(out, m, i);
    out += ' ';
    append_int(out, file_tag(point_triangle(m, i)));
    out += '\n';
    o.spill();
  }
  out += "\nTetrahedra\n";
  append_int(out, static_cast<int64_t>(m.num_tetrahedra()));
  out += '\n';
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t) {
    for (uint32_t v : file_order(&m.tetrahedra[4 * t])) {
      append_int(out, int64_t{v} + 1);
      out += ' ';
    }
    append_int(out, int64_t{m.regions[t]} + 1);
    out += '\n';
    o.spill();
  }
  if (m.num_boundary() > 0) {
    out += "\nTriangles\n";
    append_int(out, static_cast<int64_t>(m.num_boundary()));
    out += '\n';
    for (std::size_t b = 0; b < m.num_boundary(); ++b) {
      for (int k = 0; k < 3; ++k) {
        append_int(out, int64_t{m.boundary[3 * b + k]} + 1);
        out += ' ';
      }
      append_int(out, file_tag(m.boundary_tags[b]));
      out += '\n';
      o.spill();
    }
  }
  out += "\nEnd\n";
}

}  // namespace sweepcdt::io::detail
