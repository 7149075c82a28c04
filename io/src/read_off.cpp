// OFF (Geomview's Object File Format), 3D, ascii: "[ST][C][N]OFF", counts "nv nf ne", then one vertex
// per line (x y z, then optional normal/colour/texture values that are ignored), then one face per
// line ("k i_0 ... i_{k-1}", then an optional colour that is ignored). Faces are planar polygons.
#include <array>

#include "reader_util.h"

namespace sweepcdt::io::detail {
namespace {

// Smallest vertex line "0 0 0\n" and face line "3 0 1 2\n": bounds counts by the file size.
constexpr uint64_t kMinVertexBytes = 6;
constexpr uint64_t kMinFaceBytes = 8;

// The header keyword: optional ST, C, N prefixes (texture coordinates, colours, normals) before "OFF".
// 4OFF/nOFF (other dimensions) and "OFF BINARY" are refused.
void check_keyword(const TextScanner& text, std::string_view keyword) {
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF")
    text.fail(InputErrorKind::Syntax, "an OFF file starts with the keyword OFF");
  std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix.find_first_of("4n") != std::string_view::npos)
    text.fail(InputErrorKind::Unsupported, "'" + std::string(keyword) + "' (an OFF of another dimension than 3)");
  for (std::string_view part : {"ST", "C", "N"})
    if (prefix.substr(0, part.size()) == part) prefix.remove_prefix(part.size());
  if (!prefix.empty()) text.fail(InputErrorKind::Syntax, "unknown OFF keyword '" + std::string(keyword) + "'");
}

}  // namespace

void read_off(std::string_view bytes, Soup& soup) {
  TextScanner text(bytes, soup.file, '#');
  std::vector<std::string_view> tokens;
  if (!text.next_line(tokens)) text.fail(InputErrorKind::Truncated, "the file is empty");
  check_keyword(text, tokens[0]);
  if (tokens.size() > 1 && tokens[1] == "BINARY") text.fail(InputErrorKind::Unsupported, "binary OFF");
  // The counts follow the keyword on the same line or on the next.
  std::vector<std::string_view> counts(tokens.begin() + 1, tokens.end());
  if (counts.empty()) {
    if (!text.next_line(tokens)) text.fail(InputErrorKind::Truncated, "the file ends before the vertex and face counts");
    counts = tokens;
  }
  if (counts.size() < 2) text.fail(InputErrorKind::Syntax, "expected the counts 'vertices faces edges'");
  const auto nv = static_cast<uint64_t>(text.to_integer(counts[0], "the vertex count", 0));
  const auto nf = static_cast<uint64_t>(text.to_integer(counts[1], "the face count", 0));
  soup.points.reserve(3 * plausible_count(nv, kMinVertexBytes, text.bytes_left() + 1, "vertices", soup.file, text.here()));
  soup.triangles.reserve(3 * plausible_count(nf, kMinFaceBytes, text.bytes_left() + 1, "faces", soup.file, text.here()));

  for (uint64_t v = 0; v < nv; ++v) {
    if (!text.next_line(tokens))
      text.fail(InputErrorKind::Truncated, "the file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    if (tokens.size() < 3) text.fail(InputErrorKind::Syntax, "vertex " + std::to_string(v) + " needs three coordinates");
    add_point(soup, text.to_double(tokens[0], "a coordinate"), text.to_double(tokens[1], "a coordinate"),
              text.to_double(tokens[2], "a coordinate"), text.here());
  }
  std::vector<uint32_t> ids;
  for (uint64_t f = 0; f < nf; ++f) {
    if (!text.next_line(tokens))
      text.fail(InputErrorKind::Truncated, "the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const auto k = static_cast<uint64_t>(text.to_integer(tokens[0], "the face's vertex count", 0));
    if (k < 3) text.fail(InputErrorKind::BadPolygon, "face " + std::to_string(f) + " has " + std::to_string(k) + " vertices (at least 3 needed)");
    if (tokens.size() < k + 1)
      text.fail(InputErrorKind::Syntax, "face " + std::to_string(f) + " announces " + std::to_string(k) + " vertices but lists " + std::to_string(tokens.size() - 1));
    ids.clear();
    for (uint64_t i = 1; i <= k; ++i) {
      const int64_t id = text.to_integer(tokens[i], "a vertex index");
      if (id < 0 || static_cast<uint64_t>(id) >= nv)
        text.fail(InputErrorKind::IndexOutOfRange, "face " + std::to_string(f) + " names vertex " + std::to_string(id) + ", but there are " + std::to_string(nv));
      ids.push_back(static_cast<uint32_t>(id));
    }
    add_polygon(soup, ids, text.here());
  }
}

}  // namespace sweepcdt::io::detail
