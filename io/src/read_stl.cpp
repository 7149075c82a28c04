// STL, ascii and binary. Binary: an 80-byte header, a uint32 triangle count n, then n records of
// 50 bytes (normal, three float32 corners, a 2-byte attribute). The file is binary exactly when its
// size is 84 + 50 n — many binary files begin with the word "solid" too, so that word decides nothing.
// Normals are ignored: the corner order defines the orientation.
#include "reader_util.h"

namespace sweepcdt::io::detail {

void read_stl_binary(std::string_view bytes, Soup& soup) {
  ByteReader in(bytes, soup.file);
  in.skip(80, "the 80-byte header");
  const uint32_t n = in.read<uint32_t>(false, "the triangle count");
  const uint64_t expected = 84 + 50 * uint64_t{n};
  if (bytes.size() != expected)
    fail(InputErrorKind::SizeMismatch, soup.file, Location::byte(80),
         "binary STL header announces " + std::to_string(n) + " triangles, which take " + std::to_string(expected) +
             " bytes, but the file has " + std::to_string(bytes.size()));
  soup.points.reserve(9 * std::size_t{n});
  soup.triangles.reserve(3 * std::size_t{n});
  for (uint32_t t = 0; t < n; ++t) {
    const Location where = Location::of("triangle", t);
    in.skip(12, "a normal");
    for (int corner = 0; corner < 3; ++corner) {
      const double x = in.read<float>(false, "a corner");
      const double y = in.read<float>(false, "a corner");
      const double z = in.read<float>(false, "a corner");
      add_point(soup, x, y, z, where);
    }
    in.skip(2, "the attribute byte count");
    const auto first = static_cast<uint32_t>(soup.num_points() - 3);
    soup.triangles.insert(soup.triangles.end(), {first, first + 1, first + 2});
  }
}

void read_stl_ascii(std::string_view bytes, Soup& soup) {
  TextScanner text(bytes, soup.file, '\0');
  auto expect = [&](std::string_view keyword) {
    const std::string_view token = text.next_token();
    if (token.empty()) text.fail(InputErrorKind::Truncated, "the file ends where '" + std::string(keyword) + "' was expected");
    if (token != keyword) text.fail(InputErrorKind::Syntax, "expected '" + std::string(keyword) + "', found '" + std::string(token.substr(0, 40)) + "'");
  };
  expect("solid");
  text.skip_rest_of_line();  // the solid's name
  // Several solids may follow one another; each ends with "endsolid [name]".
  for (std::string_view token = text.next_token(); !token.empty(); token = text.next_token()) {
    if (token == "endsolid") {
      text.skip_rest_of_line();
      const std::string_view next = text.next_token();
      if (next.empty()) return;
      if (next != "solid") text.fail(InputErrorKind::Syntax, "expected 'solid' or the end of the file after 'endsolid'");
      text.skip_rest_of_line();
      continue;
    }
    if (token != "facet") text.fail(InputErrorKind::Syntax, "expected 'facet' or 'endsolid', found '" + std::string(token.substr(0, 40)) + "'");
    text.skip_rest_of_line();  // "normal nx ny nz" is ignored
    expect("outer");
    expect("loop");
    for (int corner = 0; corner < 3; ++corner) {
      expect("vertex");
      const double x = text.to_double(text.next_token(), "a coordinate");
      const double y = text.to_double(text.next_token(), "a coordinate");
      const double z = text.to_double(text.next_token(), "a coordinate");
      add_point(soup, x, y, z, text.here());
    }
    const std::string_view end = text.next_token();
    if (end == "vertex") text.fail(InputErrorKind::Unsupported, "a facet with more than three vertices");
    if (end.empty()) text.fail(InputErrorKind::Truncated, "the file ends inside a facet");
    if (end != "endloop") text.fail(InputErrorKind::Syntax, "expected 'endloop'");
    expect("endfacet");
    const auto first = static_cast<uint32_t>(soup.num_points() - 3);
    soup.triangles.insert(soup.triangles.end(), {first, first + 1, first + 2});
  }
  text.fail(InputErrorKind::Truncated, "the file ends before 'endsolid'");
}

}  // namespace sweepcdt::io::detail
