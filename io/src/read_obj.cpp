// Wavefront OBJ, geometry only: "v x y z [w | r g b]" and "f v[/vt][/vn] ..." (1-based, negative =
// relative to the last vertex defined). Texture coordinates, normals, groups, materials, smoothing,
// lines and points are ignored; free-form geometry (curves, surfaces) is refused. A face may only
// name vertices defined above it, as the format describes.
#include "reader_util.h"

namespace sweepcdt::io::detail {
namespace {

bool one_of(std::string_view token, std::initializer_list<std::string_view> words) {
  for (auto w : words)
    if (token == w) return true;
  return false;
}

}  // namespace

void read_obj(std::string_view bytes, Soup& soup) {
  TextScanner text(bytes, soup.file, '#');
  std::vector<std::string_view> tokens;
  std::vector<uint32_t> ids;
  uint64_t face = 0;
  while (text.next_line(tokens)) {
    const std::string_view key = tokens[0];
    if (key == "v") {
      if (tokens.size() < 4) text.fail(InputErrorKind::Syntax, "a vertex needs three coordinates");
      add_point(soup, text.to_double(tokens[1], "a coordinate"), text.to_double(tokens[2], "a coordinate"),
                text.to_double(tokens[3], "a coordinate"), text.here());
    } else if (key == "f") {
      if (tokens.size() < 4) text.fail(InputErrorKind::BadPolygon, "face " + std::to_string(face) + " has fewer than three vertices");
      ids.clear();
      const auto defined = static_cast<int64_t>(soup.num_points());
      for (std::size_t i = 1; i < tokens.size(); ++i) {
        const std::string_view ref = tokens[i].substr(0, tokens[i].find('/'));
        const int64_t index = text.to_integer(ref, "a vertex index");
        const int64_t id = index > 0 ? index - 1 : defined + index;
        if (index == 0 || id < 0 || id >= defined)
          text.fail(InputErrorKind::IndexOutOfRange, "face " + std::to_string(face) + " names vertex " + std::to_string(index) +
                                                         ", but " + std::to_string(defined) + " vertices are defined above it");
        ids.push_back(static_cast<uint32_t>(id));
      }
      add_polygon(soup, ids, text.here());
      ++face;
    } else if (one_of(key, {"cstype", "curv", "curv2", "surf", "deg", "bmat", "step", "parm", "trim", "hole", "scrv", "sp", "end", "con"})) {
      text.fail(InputErrorKind::Unsupported, "free-form geometry ('" + std::string(key) + "')");
    } else if (!one_of(key, {"vt", "vn", "vp", "o", "g", "s", "mg", "usemtl", "mtllib", "l", "p",
                             "lod", "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech", "stech"})) {
      text.fail(InputErrorKind::Syntax, "unknown OBJ statement '" + std::string(key.substr(0, 40)) + "'");
    }
  }
}

}  // namespace sweepcdt::io::detail
