// Abaqus / CalculiX .inp reader: *NODE, *ELEMENT of TYPE=C3D4 (region from ELSET=REGION<k> as k-1,
// other ELSET names get the next free region ids, no ELSET: region 0), and element-face surfaces
// (*SURFACE, TYPE=ELEMENT: "element, S<face>") as boundary triangles (no tags: the format has none).
// Other keywords and their data lines are read past; other element types are refused. Keywords and
// parameters are case-insensitive; "**" lines are comments. *INCLUDE is refused (a mesh is one file).
#include <algorithm>
#include <cctype>
#include <map>
#include <unordered_map>

#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (!out.empty() && out.back().empty()) out.pop_back();  // a trailing comma
  return out;
}

}  // namespace

VolumeMesh read_abaqus(std::string_view bytes, const std::string& file) {
  VolumeMesh m;
  std::unordered_map<int64_t, uint32_t> node_index;
  struct Element {
    int64_t id;
    std::array<uint32_t, 4> v;  // sweepcdt order
    int32_t region;
  };
  std::vector<Element> elements;
  std::vector<std::pair<int64_t, int>> faces;  // (element id, S number) of the boundary surface
  std::map<std::string, int32_t> region_of_set;
  int32_t next_region = 0;

  enum class Block { None, Node, Element, Surface } block = Block::None;
  int32_t current_region = 0;
  uint64_t line_number = 0;
  std::size_t pos = 0;
  auto bad = [&](InputErrorKind kind, const std::string& why) { fail(kind, file, Location::line(line_number), why); };
  auto integer = [&](std::string_view t, const char* what) {
    int64_t v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) bad(InputErrorKind::Syntax, std::string("expected ") + what + ", found '" + std::string(t.substr(0, 40)) + "'");
    return v;
  };
  auto real = [&](std::string_view t) {
    double v = 0;
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) bad(InputErrorKind::Syntax, "expected a coordinate, found '" + std::string(t.substr(0, 40)) + "'");
    if (!std::isfinite(v)) bad(InputErrorKind::NonFinite, "a coordinate is not finite");
    return v;
  };

  while (pos < bytes.size()) {
    const std::size_t eol = bytes.find('\n', pos);
    const std::string_view line = trim(bytes.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos));
    pos = eol == std::string_view::npos ? bytes.size() : eol + 1;
    ++line_number;
    if (line.empty() || line.starts_with("**")) continue;
    const auto fields = split(line);
    if (line.front() == '*') {
      const std::string keyword = upper(fields[0]);
      std::map<std::string, std::string> parameter;
      for (std::size_t i = 1; i < fields.size(); ++i) {
        const std::size_t eq = fields[i].find('=');
        parameter[upper(trim(fields[i].substr(0, eq)))] = eq == std::string_view::npos ? "" : upper(trim(fields[i].substr(eq + 1)));
      }
      block = Block::None;
      if (keyword == "*NODE") {
        block = Block::Node;
      } else if (keyword == "*ELEMENT") {
        if (parameter["TYPE"] != "C3D4") bad(InputErrorKind::Unsupported, "element type '" + parameter["TYPE"] + "' (only C3D4 tetrahedra)");
        block = Block::Element;
        current_region = 0;
        if (const auto it = parameter.find("ELSET"); it != parameter.end()) {
          auto [r, fresh] = region_of_set.try_emplace(it->second, 0);
          if (fresh) {
            const std::string& name = it->second;
            int64_t k = 0;
            const bool numbered = name.starts_with("REGION") && name.size() > 6 && name.size() < 16 &&
                                  std::from_chars(name.data() + 6, name.data() + name.size(), k).ptr == name.data() + name.size() && k >= 1;
            r->second = numbered ? static_cast<int32_t>(std::min<int64_t>(k - 1, INT32_MAX - 1)) : next_region;
          }
          next_region = std::max(next_region, r->second + 1);
          current_region = r->second;
        }
      } else if (keyword == "*SURFACE") {
        if (parameter.count("TYPE") && parameter["TYPE"] != "ELEMENT") bad(InputErrorKind::Unsupported, "*SURFACE of TYPE=" + parameter["TYPE"] + " (only element-face surfaces)");
        block = Block::Surface;
      } else if (keyword == "*INCLUDE") {
        bad(InputErrorKind::Unsupported, "*INCLUDE (a mesh in one file is read)");
      }
      continue;
    }
    switch (block) {
      case Block::None: break;
      case Block::Node: {
        if (fields.size() != 4) bad(InputErrorKind::Syntax, "a node line is 'id, x, y, z'");
        const int64_t id = integer(fields[0], "a node id");
        if (m.num_points() >= kNone - 1) bad(InputErrorKind::AbsurdCount, "more than 2^32 - 2 nodes");
        if (!node_index.emplace(id, static_cast<uint32_t>(m.num_points())).second) bad(InputErrorKind::Syntax, "node " + std::to_string(id) + " defined twice");
        m.points.insert(m.points.end(), {real(fields[1]), real(fields[2]), real(fields[3])});
        break;
      }
      case Block::Element: {
        if (fields.size() != 5) bad(InputErrorKind::Syntax, "a C3D4 line is 'id, n1, n2, n3, n4'");
        Element e{integer(fields[0], "an element id"), {}, current_region};
        uint32_t v[4];
        for (int k = 0; k < 4; ++k) {
          const int64_t node = integer(fields[k + 1], "a node id");
          const auto it = node_index.find(node);
          if (it == node_index.end()) bad(InputErrorKind::IndexOutOfRange, "element " + std::to_string(e.id) + " names node " + std::to_string(node) + ", not defined before it");
          v[k] = it->second;
        }
        e.v = file_order(v);
        elements.push_back(e);
        break;
      }
      case Block::Surface: {
        if (fields.size() != 2) bad(InputErrorKind::Syntax, "a surface line is 'element, S<face>'");
        const std::string face = upper(fields[1]);
        if (face.size() != 2 || face[0] != 'S' || face[1] < '1' || face[1] > '4') bad(InputErrorKind::Syntax, "face '" + face + "' (S1 .. S4)");
        faces.push_back({integer(fields[0], "an element id"), face[1] - '0'});
        break;
      }
    }
  }

  std::stable_sort(elements.begin(), elements.end(), [](const Element& a, const Element& b) { return a.id < b.id; });
  std::unordered_map<int64_t, std::size_t> element_index;
  for (std::size_t t = 0; t < elements.size(); ++t) {
    if (!element_index.emplace(elements[t].id, t).second) fail(InputErrorKind::Syntax, file, Location::none(), "element " + std::to_string(elements[t].id) + " defined twice");
    m.tetrahedra.insert(m.tetrahedra.end(), elements[t].v.begin(), elements[t].v.end());
    m.regions.push_back(elements[t].region);
  }
  for (const auto& [id, s] : faces) {
    const auto it = element_index.find(id);
    if (it == element_index.end()) fail(InputErrorKind::IndexOutOfRange, file, Location::none(), "surface names element " + std::to_string(id) + ", which does not exist");
    int i = 0;
    while (abaqus_face_without(i) != s) ++i;
    const auto f = outward_facet(elements[it->second].v.data(), i);
    m.boundary.insert(m.boundary.end(), f.begin(), f.end());
    m.boundary_tags.push_back(kNone);
  }
  m.num_input_points = static_cast<uint32_t>(m.num_points());
  return m;
}

}  // namespace sweepcdt::io::detail
