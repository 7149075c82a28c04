// VTK XML unstructured grid (.vtu) reader for ascii files like the ones write_volume_mesh() writes:
// one Piece, Points, Cells (connectivity/offsets/types), optional CellData region / boundary_tag and
// PointData steiner and input_triangle. Cell types 10 (tetrahedron) and 5 (triangle: boundary); binary or appended data,
// compression and other cell types are refused by name. Not a general XML parser: tags are found by
// name, which is all a .vtu needs.
#include <charconv>
#include <optional>

#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {
namespace {

class Vtu {
 public:
  Vtu(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  uint64_t line_at(std::size_t pos) const {
    uint64_t line = 1;
    for (std::size_t i = 0; i < pos && i < text_.size(); ++i) line += text_[i] == '\n';
    return line;
  }
  [[noreturn]] void fail_at(std::size_t pos, InputErrorKind kind, const std::string& why) const {
    fail(kind, file_, Location::line(line_at(pos)), why);
  }
  // The value of attribute `name` inside the tag starting at `tag` (up to its '>'), or nullopt.
  std::optional<std::string_view> attribute(std::size_t tag, std::string_view name) const {
    if (tag >= text_.size()) return std::nullopt;  // no such tag
    const std::size_t end = text_.find('>', tag);
    const std::string_view t = text_.substr(tag, end == std::string_view::npos ? std::string_view::npos : end - tag);
    for (std::size_t p = t.find(name); p != std::string_view::npos; p = t.find(name, p + 1)) {
      if (p == 0 || (t[p - 1] != ' ' && t[p - 1] != '\n' && t[p - 1] != '\t')) continue;
      std::size_t q = p + name.size();
      if (q + 1 >= t.size() || t[q] != '=' || (t[q + 1] != '"' && t[q + 1] != '\'')) continue;
      const char quote = t[q + 1];
      const std::size_t close = t.find(quote, q + 2);
      if (close == std::string_view::npos) fail_at(tag, InputErrorKind::Syntax, "unterminated attribute " + std::string(name));
      return t.substr(q + 2, close - q - 2);
    }
    return std::nullopt;
  }
  uint64_t count_attribute(std::size_t tag, std::string_view name) const {
    const auto v = attribute(tag, name);
    uint64_t n = 0;
    if (!v || std::from_chars(v->data(), v->data() + v->size(), n).ec != std::errc() )
      fail_at(tag, InputErrorKind::Syntax, "missing or bad " + std::string(name));
    return n;
  }

  struct Array {
    std::size_t tag = std::string_view::npos;  // position of "<DataArray"
    std::size_t begin = 0, end = 0;            // its content
  };
  // The DataArray named `name` between `from` and `to` (the first one when `name` is empty).
  Array find_array(std::size_t from, std::size_t to, std::string_view name) const {
    for (std::size_t p = text_.find("<DataArray", from); p != std::string_view::npos && p < to; p = text_.find("<DataArray", p + 1)) {
      const auto n = attribute(p, "Name");
      if (!name.empty() && (!n || *n != name)) continue;
      const auto format = attribute(p, "format");
      if (!format || *format != "ascii")
        fail_at(p, InputErrorKind::Unsupported, "DataArray " + std::string(name) + " is not format=\"ascii\" (binary and appended .vtu are not read)");
      const std::size_t open_end = text_.find('>', p);
      const std::size_t close = text_.find("</DataArray>", p);
      if (open_end == std::string_view::npos || close == std::string_view::npos) fail_at(p, InputErrorKind::Truncated, "unterminated DataArray");
      return {p, open_end + 1, close};
    }
    return {};
  }
  // The numbers of an array, exactly `count` of them, as T.
  template <class T>
  std::vector<T> numbers(const Array& a, uint64_t count, const char* what) const {
    std::vector<T> out;
    if (count > (a.end - a.begin + 1) / 2)
      fail_at(a.tag, InputErrorKind::AbsurdCount, std::to_string(count) + " " + what + " announced, but the array has " + std::to_string(a.end - a.begin) + " bytes");
    out.reserve(count);
    std::size_t p = a.begin;
    while (true) {
      while (p < a.end && (text_[p] == ' ' || text_[p] == '\n' || text_[p] == '\r' || text_[p] == '\t')) ++p;
      if (p >= a.end) break;
      std::size_t q = p;
      while (q < a.end && !(text_[q] == ' ' || text_[q] == '\n' || text_[q] == '\r' || text_[q] == '\t')) ++q;
      if (out.size() == count) fail_at(p, InputErrorKind::SizeMismatch, std::string(what) + ": more values than the " + std::to_string(count) + " expected");
      T v{};
      const auto [end, ec] = std::from_chars(text_.data() + p, text_.data() + q, v);
      if (ec != std::errc() || end != text_.data() + q) fail_at(p, InputErrorKind::Syntax, std::string("bad number in ") + what);
      if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(v)) fail_at(p, InputErrorKind::NonFinite, std::string("non-finite value in ") + what);
      out.push_back(v);
      p = q;
    }
    if (out.size() != count)
      fail_at(a.end, InputErrorKind::Truncated, std::string(what) + ": " + std::to_string(out.size()) + " values, " + std::to_string(count) + " expected");
    return out;
  }
  std::size_t find(std::string_view s, std::size_t from = 0) const { return text_.find(s, from); }
  std::size_t size() const { return text_.size(); }

 private:
  std::string_view text_;
  const std::string& file_;
};

}  // namespace

VolumeMesh read_vtu(std::string_view bytes, const std::string& file) {
  const Vtu x(bytes, file);
  const std::size_t grid = x.find("<UnstructuredGrid");
  if (grid == std::string_view::npos) fail(InputErrorKind::Unsupported, file, Location::none(), "not a VTK UnstructuredGrid file");
  if (const auto c = x.attribute(x.find("<VTKFile"), "compressor"); c && !c->empty())
    x.fail_at(0, InputErrorKind::Unsupported, "compressed .vtu");
  const std::size_t piece = x.find("<Piece", grid);
  if (piece == std::string_view::npos) x.fail_at(grid, InputErrorKind::Truncated, "no Piece");
  if (x.find("<Piece", piece + 1) != std::string_view::npos) x.fail_at(piece, InputErrorKind::Unsupported, "more than one Piece");
  const uint64_t n = x.count_attribute(piece, "NumberOfPoints"), cells = x.count_attribute(piece, "NumberOfCells");
  if (n >= kNone) x.fail_at(piece, InputErrorKind::AbsurdCount, "more than 2^32 - 2 points");

  const std::size_t points_at = x.find("<Points", piece), cells_at = x.find("<Cells", piece);
  if (points_at == std::string_view::npos || cells_at == std::string_view::npos) x.fail_at(piece, InputErrorKind::Truncated, "no Points or no Cells");
  const auto coords = x.find_array(points_at, x.find("</Points>", points_at), "");
  if (coords.tag == std::string_view::npos) x.fail_at(points_at, InputErrorKind::Truncated, "Points without a DataArray");
  VolumeMesh m;
  m.points = x.numbers<double>(coords, 3 * n, "point coordinates");
  m.num_input_points = static_cast<uint32_t>(n);

  const std::size_t cells_end = x.find("</Cells>", cells_at);
  const auto conn = x.find_array(cells_at, cells_end, "connectivity"), offs = x.find_array(cells_at, cells_end, "offsets"),
             types = x.find_array(cells_at, cells_end, "types");
  if (conn.tag == std::string_view::npos || offs.tag == std::string_view::npos || types.tag == std::string_view::npos)
    x.fail_at(cells_at, InputErrorKind::Truncated, "Cells needs connectivity, offsets and types");
  const auto type = x.numbers<int64_t>(types, cells, "types");
  const auto offset = x.numbers<int64_t>(offs, cells, "offsets");
  const uint64_t total = cells ? static_cast<uint64_t>(std::max<int64_t>(offset.back(), 0)) : 0;
  const auto ids = x.numbers<int64_t>(conn, total, "connectivity");

  const std::size_t cell_data = x.find("<CellData", piece);
  std::vector<int64_t> region, tag;
  if (cell_data != std::string_view::npos) {
    const std::size_t cd_end = x.find("</CellData>", cell_data);
    if (const auto a = x.find_array(cell_data, cd_end, "region"); a.tag != std::string_view::npos) region = x.numbers<int64_t>(a, cells, "region");
    if (const auto a = x.find_array(cell_data, cd_end, "boundary_tag"); a.tag != std::string_view::npos) tag = x.numbers<int64_t>(a, cells, "boundary_tag");
  }
  const std::size_t point_data = x.find("<PointData", piece);
  if (point_data != std::string_view::npos) {
    if (const auto a = x.find_array(point_data, x.find("</PointData>", point_data), "steiner"); a.tag != std::string_view::npos) {
      const auto steiner = x.numbers<int64_t>(a, n, "steiner");
      std::size_t first = 0;
      while (first < n && steiner[first] == 0) ++first;
      m.num_input_points = static_cast<uint32_t>(first);
    }
    if (const auto a = x.find_array(point_data, x.find("</PointData>", point_data), "input_triangle"); a.tag != std::string_view::npos)
      for (const int64_t written : x.numbers<int64_t>(a, n, "input_triangle")) m.on_triangle.push_back(triangle_from_file(written));
  }

  int64_t previous = 0;
  for (uint64_t c = 0; c < cells; ++c) {
    const int corners = type[c] == 10 ? 4 : type[c] == 5 ? 3 : 0;
    if (corners == 0) x.fail_at(types.begin, InputErrorKind::Unsupported, "cell " + std::to_string(c) + " has VTK type " + std::to_string(type[c]) + " (only 10, tetrahedron, and 5, triangle)");
    if (offset[c] - previous != corners) x.fail_at(offs.begin, InputErrorKind::SizeMismatch, "offset of cell " + std::to_string(c) + " does not fit its type");
    uint32_t v[4];
    for (int k = 0; k < corners; ++k) {
      const int64_t id = ids[previous + k];
      if (id < 0 || static_cast<uint64_t>(id) >= n)
        x.fail_at(conn.begin, InputErrorKind::IndexOutOfRange, "cell " + std::to_string(c) + " names point " + std::to_string(id) + " of " + std::to_string(n));
      v[k] = static_cast<uint32_t>(id);
    }
    previous = offset[c];
    if (corners == 4) {
      for (uint32_t id : file_order(v)) m.tetrahedra.push_back(id);
      const int64_t r = region.empty() ? 1 : region[c];
      if (r < 0 || r > INT32_MAX) x.fail_at(cell_data, InputErrorKind::Syntax, "region " + std::to_string(r) + " of cell " + std::to_string(c));
      m.regions.push_back(r == 0 ? 0 : static_cast<int32_t>(r - 1));
    } else {
      m.boundary.insert(m.boundary.end(), v, v + 3);
      const int64_t g = tag.empty() ? 0 : tag[c];
      if (g < 0 || g > INT64_C(0xFFFFFFFF)) x.fail_at(cell_data, InputErrorKind::Syntax, "boundary_tag " + std::to_string(g) + " of cell " + std::to_string(c));
      m.boundary_tags.push_back(tag_from_file(g));
    }
  }
  return m;
}

}  // namespace sweepcdt::io::detail
