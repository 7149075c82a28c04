// Triangle .poly (2D): points (or a .node beside it), segments, holes, optional regional attributes.
// Segments are the PLC's constraining 1-simplices, tagged with their boundary marker when the file has
// markers, else with their index; holes become exterior notations with Triangle's meaning
// (pslg_holes.h); a regional attribute, which must be a whole number >= 0, names its region (the
// maximum-area constraint is read past: sweepcdt adds no points).
#include <cmath>

#include "poly_files.h"
#include "pslg_holes.h"

namespace sweepcdt::io::detail {

Plc<2> read_triangle_poly(const std::string& bytes, const std::filesystem::path& file) {
  const std::string name = file.string();
  TextScanner in(bytes, name, '#');
  std::filesystem::path node_file = file;
  node_file.replace_extension(".node");
  NodeList nodes = read_node_list(in, 2, node_file);
  Plc<2> plc;
  plc.points = std::move(nodes.points);
  const uint64_t n = plc.num_points();

  const uint64_t m = static_cast<uint64_t>(in.to_integer(in.next_token(), "number of segments", 0, INT64_MAX));
  if (m > in.bytes_left() / 6) in.fail(InputErrorKind::AbsurdCount, std::to_string(m) + " segments announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
  const bool markers = in.to_integer(in.next_token(), "number of segment markers", 0, 1) == 1;
  plc.simplices.reserve(2 * m);
  for (uint64_t j = 0; j < m; ++j) {
    in.to_integer(in.next_token(), "a segment id");
    for (int k = 0; k < 2; ++k) {
      const int64_t v = in.to_integer(in.next_token(), "an endpoint");
      if (v < nodes.base || v - nodes.base >= static_cast<int64_t>(n))
        in.fail(InputErrorKind::IndexOutOfRange, "segment endpoint " + std::to_string(v) + " does not exist (" + std::to_string(n) + " points from " + std::to_string(nodes.base) + ")");
      plc.simplices.push_back(static_cast<uint32_t>(v - nodes.base));
    }
    if (plc.simplices[2 * j] == plc.simplices[2 * j + 1]) in.fail(InputErrorKind::BadPolygon, "segment with both endpoints " + std::to_string(plc.simplices[2 * j] + nodes.base));
    plc.tags.push_back(markers ? static_cast<uint32_t>(in.to_integer(in.next_token(), "a segment marker", 0, UINT32_MAX - 1)) : static_cast<uint32_t>(j));
  }

  std::vector<std::array<double, 2>> holes;
  const std::string_view hole_count = in.next_token();
  if (!hole_count.empty()) {  // Triangle allows a file that ends after the segments
    const uint64_t h = static_cast<uint64_t>(in.to_integer(hole_count, "number of holes", 0, INT64_MAX));
    if (h > in.bytes_left() / 6) in.fail(InputErrorKind::AbsurdCount, std::to_string(h) + " holes announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
    for (uint64_t i = 0; i < h; ++i) {
      in.to_integer(in.next_token(), "a hole id");
      holes.push_back({in.to_double(in.next_token(), "x"), in.to_double(in.next_token(), "y")});
    }
    std::vector<std::string_view> line;
    if (in.next_line(line)) {
      const uint64_t r = static_cast<uint64_t>(in.to_integer(line[0], "number of regions", 0, INT64_MAX));
      if (line.size() != 1) in.fail(InputErrorKind::Syntax, "the region count stands alone on its line");
      if (r > in.bytes_left() / 8) in.fail(InputErrorKind::AbsurdCount, std::to_string(r) + " regions announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
      for (uint64_t i = 0; i < r; ++i) {
        if (!in.next_line(line)) in.fail(InputErrorKind::Truncated, "the file ends inside the region list");
        if (line.size() < 4 || line.size() > 5) in.fail(InputErrorKind::Syntax, "a region line is '<id> <x> <y> <attribute> [<maximum area>]'");
        const double attribute = in.to_double(line[3], "a regional attribute");
        if (attribute != std::floor(attribute) || attribute < 0 || attribute > INT32_MAX - 1)
          in.fail(InputErrorKind::Syntax, "regional attribute must be a whole number in [0, 2^31 - 2] (it names the region)");
        plc.region_seeds.push_back({{in.to_double(line[1], "x"), in.to_double(line[2], "y")}, static_cast<int32_t>(attribute)});
      }
    }
    if (!in.next_token().empty()) in.fail(InputErrorKind::Syntax, "unexpected text after the region list");
  }
  notate_from_holes(plc, holes, name);
  return plc;
}

}  // namespace sweepcdt::io::detail
