// TetGen .node / .ele / .face (as `tetgen -r` reads them back, and TetView, meshio).
//   .node  n 3 0 1            then: id x y z marker           (ids 1-based; marker: 0 for an input
//                                                              vertex, for a Steiner point the input
//                                                              triangle it lies on + 1)
//   .ele   t 4 1              then: id a b c d region+1       (positive volume; attribute = region)
//   .face  b 1                then: id a b c tag+1            (boundary, counterclockwise seen from
//                                                              outside; marker 0 = no tag)
// All three are always written (an empty .face for a mesh without boundary), so no stale file of an
// earlier run is left beside them.
#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {

void tetgen_node_text(const VolumeMesh& m, TextOut& o) {
  std::string& out = o.text;
  out += std::to_string(m.num_points()) + " 3 0 1\n";
  for (std::size_t i = 0; i < m.num_points(); ++i) {
    append_int(out, static_cast<int64_t>(i) + 1);
    out += ' ';
    append_point(out, m, i);
    out += ' ';
    append_int(out, file_tag(point_triangle(m, i)));
    out += '\n';
    o.spill();
  }
}

void tetgen_ele_text(const VolumeMesh& m, TextOut& o) {
  std::string& out = o.text;
  out += std::to_string(m.num_tetrahedra()) + " 4 1\n";
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t) {
    append_int(out, static_cast<int64_t>(t) + 1);
    for (uint32_t v : file_order(&m.tetrahedra[4 * t])) {
      out += ' ';
      append_int(out, int64_t{v} + 1);
    }
    out += ' ';
    append_int(out, int64_t{m.regions[t]} + 1);
    out += '\n';
    o.spill();
  }
}

void tetgen_face_text(const VolumeMesh& m, TextOut& o) {
  std::string& out = o.text;
  out += std::to_string(m.num_boundary()) + " 1\n";
  for (std::size_t b = 0; b < m.num_boundary(); ++b) {
    append_int(out, static_cast<int64_t>(b) + 1);
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_int(out, int64_t{m.boundary[3 * b + k]} + 1);
    }
    out += ' ';
    append_int(out, file_tag(m.boundary_tags[b]));
    out += '\n';
    o.spill();
  }
}

TetGenFiles tetgen_texts(const VolumeMesh& m) {
  return {whole_text(m, tetgen_node_text), whole_text(m, tetgen_ele_text), whole_text(m, tetgen_face_text)};
}

}  // namespace sweepcdt::io::detail
