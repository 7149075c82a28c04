// write_triangulation<D>(): Triangle (D = 2) / TetGen (D = 3) .node/.ele, and sweepcdt's .simplices
// text for any D. Exact coordinates (shortest round-trip text); atomic like the volume-mesh writers.
//
//   .node   n D 0 0          then: id x_1 .. x_D                       (ids 1-based)
//   .ele    s D+1 a          then: id v_0 .. v_D [region+1]            (a = 1 with regions, else 0)
//           D = 2: counterclockwise (sweepcdt's orient > 0 is Triangle's); D = 3: positive volume in
//           TetGen's convention, i.e. sweepcdt's last two vertices swapped.
//
//   .simplices (grammar in io/README.md):
//     simplices D
//     points N input I       then N lines of D coordinates (the first I are the PLC's points)
//     simplices S            then S lines: D+1 point ids (0-based, orient > 0 in sweepcdt's
//                            convention, det [p_i - p_D] > 0) [region]
#include <algorithm>
#include <cctype>

#include "file_io.h"
#include "reader_util.h"
#include "sweepcdt/io/plc_file.h"
#include "volume_mesh_formats.h"

namespace sweepcdt::io {
namespace {

template <int D>
void append_coordinates(std::string& out, const Triangulation<D>& tri, std::size_t i) {
  for (int k = 0; k < D; ++k) {
    if (k) out += ' ';
    detail::append_double(out, tri.points[D * i + k]);
  }
}

}  // namespace

template <int D>
void write_triangulation(const std::filesystem::path& file, const Triangulation<D>& tri, TriangulationFormat format) {
  const std::string name = file.string();
  const std::size_t n = tri.num_points(), s = tri.num_simplices();
  const bool regions = tri.regions.size() == s && s > 0;
  for (uint32_t v : tri.simplices)
    if (v >= n) detail::fail(InputErrorKind::Unsupported, name, Location::none(), "cannot write: a simplex names point " + std::to_string(v) + ", which does not exist");
  if (format == TriangulationFormat::Simplices) {
    std::string out = "simplices " + std::to_string(D) + "\npoints " + std::to_string(n) + " input " + std::to_string(tri.num_input_points) + "\n";
    for (std::size_t i = 0; i < n; ++i) {
      append_coordinates(out, tri, i);
      out += '\n';
    }
    out += "simplices " + std::to_string(s) + "\n";
    for (std::size_t t = 0; t < s; ++t) {
      for (int k = 0; k <= D; ++k) {
        if (k) out += ' ';
        detail::append_int(out, tri.simplex(t)[k]);
      }
      if (regions) out += " " + std::to_string(tri.regions[t]);
      out += '\n';
    }
    detail::write_files_atomically({{file, std::move(out)}}, name);
    return;
  }
  if constexpr (D != 2 && D != 3) {
    detail::fail(InputErrorKind::Unsupported, name, Location::none(), ".node/.ele is Triangle's (2D) and TetGen's (3D) format, not for dimension " + std::to_string(D));
  } else {
    std::string node = std::to_string(n) + " " + std::to_string(D) + " 0 0\n";
    for (std::size_t i = 0; i < n; ++i) {
      detail::append_int(node, static_cast<int64_t>(i) + 1);
      node += ' ';
      append_coordinates(node, tri, i);
      node += '\n';
    }
    std::string ele = std::to_string(s) + " " + std::to_string(D + 1) + (regions ? " 1\n" : " 0\n");
    for (std::size_t t = 0; t < s; ++t) {
      detail::append_int(ele, static_cast<int64_t>(t) + 1);
      const uint32_t* v = tri.simplex(t);
      std::array<uint32_t, D + 1> order;
      std::copy_n(v, D + 1, order.begin());
      if constexpr (D == 3) std::swap(order[2], order[3]);
      for (uint32_t id : order) {
        ele += ' ';
        detail::append_int(ele, int64_t{id} + 1);
      }
      if (regions) ele += " " + std::to_string(int64_t{tri.regions[t]} + 1);
      ele += '\n';
    }
    const auto names = detail::tetgen_names(file);
    detail::write_files_atomically({{names.node, std::move(node)}, {names.ele, std::move(ele)}}, name);
  }
}

template void write_triangulation<2>(const std::filesystem::path&, const Triangulation<2>&, TriangulationFormat);
template void write_triangulation<3>(const std::filesystem::path&, const Triangulation<3>&, TriangulationFormat);
template void write_triangulation<4>(const std::filesystem::path&, const Triangulation<4>&, TriangulationFormat);
template void write_triangulation<5>(const std::filesystem::path&, const Triangulation<5>&, TriangulationFormat);

}  // namespace sweepcdt::io
