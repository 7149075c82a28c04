// VTK XML unstructured grid (.vtu), ascii, as read by ParaView, VisIt, meshio.
//
// Cells: the tetrahedra (VTK_TETRA = 10, positive volume) first, then the boundary triangles
// (VTK_TRIANGLE = 5, counterclockwise seen from outside), so the surface is there for boundary
// conditions and for viewing; "Extract Cells By Type" or a threshold on `region` >= 1 keeps the volume.
//   CellData  region        Int32  tetrahedron: region + 1; triangle: 0
//             boundary_tag  Int64  triangle: tag + 1 (0 = none); tetrahedron: 0
//   PointData steiner       UInt8  1 for a Steiner point (id >= num_input_points), else 0
//             input_triangle Int64 a Steiner point: the input triangle it lies on + 1; else 0
#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {
namespace {

void open_array(std::string& out, const char* type, const char* name, int components = 1) {
  out += "<DataArray type=\"";
  out += type;
  out += "\" Name=\"";
  out += name;
  out += "\"";
  if (components > 1) out += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  out += " format=\"ascii\">\n";
}

}  // namespace

void vtu_text(const VolumeMesh& m, TextOut& o) {
  const std::size_t n = m.num_points(), t = m.num_tetrahedra(), b = m.num_boundary();
  std::string& out = o.text;
  out +=
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(t + b) + "\">\n";
  out += "<PointData>\n";
  open_array(out, "UInt8", "steiner");
  for (std::size_t i = 0; i < n; ++i) {
    out += i < m.num_input_points ? "0\n" : "1\n";
    o.spill();
  }
  out += "</DataArray>\n";
  open_array(out, "Int64", "input_triangle");
  for (std::size_t i = 0; i < n; ++i) {
    append_int(out, file_tag(point_triangle(m, i)));
    out += '\n';
    o.spill();
  }
  out += "</DataArray>\n</PointData>\n<Points>\n";
  open_array(out, "Float64", "Points", 3);
  for (std::size_t i = 0; i < n; ++i) {
    append_point(out, m, i);
    out += '\n';
    o.spill();
  }
  out += "</DataArray>\n</Points>\n<Cells>\n";
  open_array(out, "Int64", "connectivity");
  for (std::size_t c = 0; c < t; ++c) {
    const auto v = file_order(&m.tetrahedra[4 * c]);
    for (int k = 0; k < 4; ++k) {
      append_int(out, v[k]);
      out += k < 3 ? ' ' : '\n';
    }
    o.spill();
  }
  for (std::size_t c = 0; c < b; ++c) {
    for (int k = 0; k < 3; ++k) {
      append_int(out, m.boundary[3 * c + k]);
      out += k < 2 ? ' ' : '\n';
    }
    o.spill();
  }
  out += "</DataArray>\n";
  open_array(out, "Int64", "offsets");
  for (std::size_t c = 0; c < t + b; ++c) {
    append_int(out, static_cast<int64_t>(c < t ? 4 * (c + 1) : 4 * t + 3 * (c - t + 1)));
    out += '\n';
    o.spill();
  }
  out += "</DataArray>\n";
  open_array(out, "UInt8", "types");
  for (std::size_t c = 0; c < t + b; ++c) {
    out += c < t ? "10\n" : "5\n";
    o.spill();
  }
  out += "</DataArray>\n</Cells>\n<CellData Scalars=\"region\">\n";
  open_array(out, "Int32", "region");
  for (std::size_t c = 0; c < t + b; ++c) {
    append_int(out, c < t ? int64_t{m.regions[c]} + 1 : 0);
    out += '\n';
    o.spill();
  }
  out += "</DataArray>\n";
  open_array(out, "Int64", "boundary_tag");
  for (std::size_t c = 0; c < t + b; ++c) {
    append_int(out, c < t ? 0 : file_tag(m.boundary_tags[c - t]));
    out += '\n';
    o.spill();
  }
  out += "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace sweepcdt::io::detail
