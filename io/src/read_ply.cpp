// PLY (Stanford polygon format), ascii and binary little/big endian. Reads x, y, z of element
// "vertex" and the list "vertex_indices" (or "vertex_index") of element "face"; every other element
// and property is read past. Faces are planar polygons.
#include <array>

#include "reader_util.h"

namespace sweepcdt::io::detail {
namespace {

enum class Encoding { Ascii, LittleEndian, BigEndian };
enum class Kind { I8, U8, I16, U16, I32, U32, F32, F64 };

struct Type {
  std::string_view name;
  Kind kind;
  int bytes;
};
// Both the original names and the sized aliases (PLY 1.0 allows both).
constexpr std::array<Type, 16> kTypes{{{"char", Kind::I8, 1}, {"uchar", Kind::U8, 1}, {"short", Kind::I16, 2},
                                       {"ushort", Kind::U16, 2}, {"int", Kind::I32, 4}, {"uint", Kind::U32, 4},
                                       {"float", Kind::F32, 4}, {"double", Kind::F64, 8}, {"int8", Kind::I8, 1},
                                       {"uint8", Kind::U8, 1}, {"int16", Kind::I16, 2}, {"uint16", Kind::U16, 2},
                                       {"int32", Kind::I32, 4}, {"uint32", Kind::U32, 4}, {"float32", Kind::F32, 4},
                                       {"float64", Kind::F64, 8}}};

struct Property {
  std::string name;
  Type type{};
  bool list = false;
  Type count_type{};
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

Type parse_type(const TextScanner& text, std::string_view name) {
  for (const Type& t : kTypes)
    if (t.name == name) return t;
  text.fail(InputErrorKind::Syntax, "unknown PLY type '" + std::string(name.substr(0, 40)) + "'");
}

// Reads values of any PLY type as doubles (exact: every PLY type fits in a double).
class ValueReader {
 public:
  ValueReader(std::string_view bytes, std::size_t start, Encoding encoding, TextScanner& text, const std::string& file)
      : encoding_(encoding), binary_(bytes, file, start), text_(text) {}

  double number(const Type& type, const char* what) {
    if (encoding_ == Encoding::Ascii) {
      const std::string_view token = text_.next_token();
      if (type.kind == Kind::F32 || type.kind == Kind::F64) return text_.to_double(token, what);
      return static_cast<double>(text_.to_integer(token, what));
    }
    const bool big = encoding_ == Encoding::BigEndian;
    switch (type.kind) {
      case Kind::I8: return binary_.read<int8_t>(big, what);
      case Kind::U8: return binary_.read<uint8_t>(big, what);
      case Kind::I16: return binary_.read<int16_t>(big, what);
      case Kind::U16: return binary_.read<uint16_t>(big, what);
      case Kind::I32: return binary_.read<int32_t>(big, what);
      case Kind::U32: return binary_.read<uint32_t>(big, what);
      case Kind::F32: return binary_.read<float>(big, what);
      case Kind::F64: return binary_.read<double>(big, what);
    }
    return 0;
  }
  Location where() const { return encoding_ == Encoding::Ascii ? text_.here() : Location::byte(binary_.offset()); }
  uint64_t bytes_left() const { return encoding_ == Encoding::Ascii ? text_.bytes_left() : binary_.bytes_left(); }
  // Fewest bytes a value can take: its size in binary, a digit and a separator in ascii.
  uint64_t min_bytes(const Type& type) const { return encoding_ == Encoding::Ascii ? 2 : static_cast<uint64_t>(type.bytes); }

 private:
  Encoding encoding_;
  ByteReader binary_;
  TextScanner& text_;
};

// The header, up to and including the line "end_header".
std::vector<Element> read_header(TextScanner& text, Encoding& encoding) {
  std::vector<std::string_view> tokens;
  if (!text.next_line(tokens) || tokens[0] != "ply") text.fail(InputErrorKind::Syntax, "a PLY file starts with the line 'ply'");
  std::vector<Element> elements;
  bool have_format = false;
  while (true) {
    if (!text.next_line(tokens)) text.fail(InputErrorKind::Truncated, "the file ends inside the PLY header");
    const std::string_view key = tokens[0];
    if (key == "end_header") break;
    if (key == "comment" || key == "obj_info") continue;
    if (key == "format") {
      if (tokens.size() < 3 || tokens[2] != "1.0") text.fail(InputErrorKind::Unsupported, "PLY format line other than '<encoding> 1.0'");
      if (tokens[1] == "ascii") encoding = Encoding::Ascii;
      else if (tokens[1] == "binary_little_endian") encoding = Encoding::LittleEndian;
      else if (tokens[1] == "binary_big_endian") encoding = Encoding::BigEndian;
      else text.fail(InputErrorKind::Unsupported, "PLY encoding '" + std::string(tokens[1].substr(0, 40)) + "'");
      have_format = true;
    } else if (key == "element") {
      if (tokens.size() != 3) text.fail(InputErrorKind::Syntax, "expected 'element NAME COUNT'");
      elements.push_back({std::string(tokens[1]), static_cast<uint64_t>(text.to_integer(tokens[2], "an element count", 0)), {}});
    } else if (key == "property") {
      if (elements.empty()) text.fail(InputErrorKind::Syntax, "a property before any element");
      Property p;
      if (tokens.size() == 5 && tokens[1] == "list") {
        p.list = true;
        p.count_type = parse_type(text, tokens[2]);
        if (p.count_type.kind == Kind::F32 || p.count_type.kind == Kind::F64) text.fail(InputErrorKind::Syntax, "a list count must be an integer type");
        p.type = parse_type(text, tokens[3]);
        p.name = tokens[4];
      } else if (tokens.size() == 3) {
        p.type = parse_type(text, tokens[1]);
        p.name = tokens[2];
      } else {
        text.fail(InputErrorKind::Syntax, "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      }
      elements.back().properties.push_back(std::move(p));
    } else {
      text.fail(InputErrorKind::Syntax, "unknown PLY header line '" + std::string(key.substr(0, 40)) + "'");
    }
  }
  if (!have_format) text.fail(InputErrorKind::Syntax, "the PLY header has no format line");
  return elements;
}

int find_property(const Element& e, std::initializer_list<std::string_view> names, bool list) {
  for (std::size_t i = 0; i < e.properties.size(); ++i)
    for (auto n : names)
      if (e.properties[i].name == n && e.properties[i].list == list) return static_cast<int>(i);
  return -1;
}

}  // namespace

void read_ply(std::string_view bytes, Soup& soup) {
  TextScanner text(bytes, soup.file, '\0');
  Encoding encoding = Encoding::Ascii;
  const std::vector<Element> elements = read_header(text, encoding);
  // Binary data starts right after the newline that ends "end_header".
  std::size_t data_start = text.offset();
  while (data_start < bytes.size() && bytes[data_start] != '\n') ++data_start;
  if (data_start < bytes.size()) ++data_start;
  ValueReader values(bytes, data_start, encoding, text, soup.file);

  uint64_t vertices = 0;
  bool have_vertices = false;
  std::vector<uint32_t> ids;
  for (const Element& e : elements) {
    uint64_t min_bytes = 0;
    for (const Property& p : e.properties) min_bytes += values.min_bytes(p.list ? p.count_type : p.type);
    if (e.count > 0 && min_bytes == 0) text.fail(InputErrorKind::Syntax, "element '" + e.name + "' has no properties");
    const uint64_t plausible = plausible_count(e.count, std::max<uint64_t>(min_bytes, 1), values.bytes_left(), "'" + e.name + "' elements", soup.file, values.where());
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    std::array<int, 3> xyz{-1, -1, -1};
    int indices = -1;
    if (is_vertex) {
      xyz = {find_property(e, {"x"}, false), find_property(e, {"y"}, false), find_property(e, {"z"}, false)};
      if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0) text.fail(InputErrorKind::Unsupported, "a PLY vertex element without x, y and z");
      soup.points.reserve(3 * plausible);
      vertices = e.count;
      have_vertices = true;
    }
    if (is_face) {
      indices = find_property(e, {"vertex_indices", "vertex_index"}, true);
      if (indices < 0) text.fail(InputErrorKind::Unsupported, "a PLY face element without the list 'vertex_indices'");
      if (!have_vertices) text.fail(InputErrorKind::Unsupported, "PLY faces before the vertices");
      soup.triangles.reserve(3 * plausible);
    }
    for (uint64_t i = 0; i < e.count; ++i) {
      std::array<double, 3> point{};
      const Location where = is_face ? Location::of("face", i) : values.where();
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (!p.list) {
          const double v = values.number(p.type, "a property value");
          for (int axis = 0; axis < 3; ++axis)
            if (xyz[axis] == static_cast<int>(k)) point[axis] = v;
          continue;
        }
        const double n = values.number(p.count_type, "a list count");
        if (n < 0) fail(InputErrorKind::Syntax, soup.file, values.where(), "negative list length " + std::to_string(n));
        const auto length = static_cast<uint64_t>(n);
        ids.reserve(plausible_count(length, values.min_bytes(p.type), values.bytes_left(), "list entries", soup.file, values.where()));
        if (static_cast<int>(k) == indices) ids.clear();
        for (uint64_t j = 0; j < length; ++j) {
          const double v = values.number(p.type, "a list entry");
          if (static_cast<int>(k) != indices) continue;
          if (v < 0 || v >= static_cast<double>(vertices) || v != static_cast<double>(static_cast<uint64_t>(v)))
            fail(InputErrorKind::IndexOutOfRange, soup.file, where,
                 "names vertex " + std::to_string(static_cast<int64_t>(v)) + ", but there are " + std::to_string(vertices));
          ids.push_back(static_cast<uint32_t>(v));
        }
        if (static_cast<int>(k) == indices && length < 3) fail(InputErrorKind::BadPolygon, soup.file, where, "has fewer than three vertices");
      }
      if (is_vertex) add_point(soup, point[0], point[1], point[2], Location::of("vertex", i));
      if (is_face) add_polygon(soup, ids, where);
    }
  }
}

}  // namespace sweepcdt::io::detail
