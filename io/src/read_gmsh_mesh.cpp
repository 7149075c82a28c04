// Gmsh .msh ascii reader, versions 4.1 and 2.2. Tetrahedra (type 4) and triangles (type 2, read as
// boundary triangles) are kept, points (15) and lines (1) read past, other element types refused.
// Region of a tetrahedron: its physical tag - 1 (2.2: first tag; 4.1: the volume entity's first
// physical tag, else the entity tag). Boundary tag of a triangle: its elementary/entity tag - 1
// (2147483647: none). Elements are put in order of their element tags, nodes in order of appearance.
#include <algorithm>
#include <limits>
#include <map>

#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {
namespace {

constexpr int64_t kUntaggedSurface = std::numeric_limits<int32_t>::max();

struct Reader {
  TextScanner& in;
  VolumeMesh m;
  std::vector<uint32_t> index_of_tag;  // node tag -> point index (kNone: no such node)
  std::map<int64_t, int64_t> volume_physical;
  struct Element {
    int64_t tag;
    std::array<uint32_t, 4> v;
    int64_t label;  // region as written, or surface entity
  };
  std::vector<Element> tets, triangles;

  void expect_end(std::string_view section) {
    const auto t = in.next_token();
    if (t != "$End" + std::string(section)) in.fail(InputErrorKind::Syntax, "expected $End" + std::string(section));
  }
  void node_table(uint64_t max_tag, uint64_t count) {
    // Tags index a table, so they must be dense enough that it stays proportional to the file.
    if (max_tag > 4 * count + 1024) in.fail(InputErrorKind::Unsupported, "node tags up to " + std::to_string(max_tag) + " for " + std::to_string(count) + " nodes (too sparse)");
    index_of_tag.assign(max_tag + 1, kNone);
    m.points.reserve(3 * count);
  }
  void add_node(int64_t tag, double x, double y, double z) {
    if (tag < 1 || static_cast<uint64_t>(tag) >= index_of_tag.size()) in.fail(InputErrorKind::IndexOutOfRange, "node tag " + std::to_string(tag) + " outside the announced range");
    if (index_of_tag[tag] != kNone) in.fail(InputErrorKind::Syntax, "node " + std::to_string(tag) + " defined twice");
    index_of_tag[tag] = static_cast<uint32_t>(m.num_points());
    m.points.insert(m.points.end(), {x, y, z});
  }
  uint32_t node(std::string_view token) {
    const int64_t tag = in.to_integer(token, "node tag");
    if (tag < 1 || static_cast<uint64_t>(tag) >= index_of_tag.size() || index_of_tag[tag] == kNone)
      in.fail(InputErrorKind::IndexOutOfRange, "element names node " + std::to_string(tag) + ", which does not exist");
    return index_of_tag[tag];
  }
  // An element of `type` with tag `tag` (types 1 and 15, edges and points, are read past).
  void element(int64_t tag, int64_t type, int64_t label) {
    const int corners = type == 4 ? 4 : type == 2 ? 3 : type == 1 ? 2 : type == 15 ? 1 : 0;
    if (corners == 0) in.fail(InputErrorKind::Unsupported, "element type " + std::to_string(type) + " (only 4 tetrahedron, 2 triangle; 1 and 15 are read past)");
    Element e{tag, {}, label};
    for (int k = 0; k < corners; ++k) {
      const uint32_t v = node(in.next_token());
      if (k < 4) e.v[k] = v;
    }
    if (type == 4) tets.push_back(e);
    if (type == 2) triangles.push_back(e);
  }

  void nodes41() {
    const uint64_t blocks = read_count(in, "node blocks", 8), count = read_count(in, "nodes", 8);
    in.to_integer(in.next_token(), "min node tag");
    const uint64_t max_tag = static_cast<uint64_t>(in.to_integer(in.next_token(), "max node tag", 0, INT64_MAX));
    node_table(max_tag, count);
    for (uint64_t b = 0; b < blocks; ++b) {
      in.to_integer(in.next_token(), "entity dimension", 0, 3);
      in.to_integer(in.next_token(), "entity tag");
      const bool parametric = in.to_integer(in.next_token(), "parametric", 0, 1) == 1;
      const uint64_t k = read_count(in, "nodes in block", 8);
      std::vector<int64_t> tags(k);
      for (auto& t : tags) t = in.to_integer(in.next_token(), "node tag");
      for (int64_t t : tags) {
        const double x = in.to_double(in.next_token(), "x"), y = in.to_double(in.next_token(), "y"), z = in.to_double(in.next_token(), "z");
        add_node(t, x, y, z);
        if (parametric) in.fail(InputErrorKind::Unsupported, "parametric nodes");
      }
    }
    if (m.num_points() != count) in.fail(InputErrorKind::SizeMismatch, std::to_string(m.num_points()) + " nodes in the blocks, " + std::to_string(count) + " announced");
  }
  void entities41() {
    uint64_t counts[4];
    for (auto& c : counts) c = read_count(in, "entities", 8);
    for (int dim = 0; dim < 4; ++dim)
      for (uint64_t e = 0; e < counts[dim]; ++e) {
        const int64_t tag = in.to_integer(in.next_token(), "entity tag");
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) in.to_double(in.next_token(), "bounding box");
        const uint64_t physicals = read_count(in, "physical tags", 2);
        for (uint64_t p = 0; p < physicals; ++p) {
          const int64_t ph = in.to_integer(in.next_token(), "physical tag");
          if (dim == 3 && p == 0) volume_physical[tag] = ph;
        }
        if (dim > 0) {
          const uint64_t bounding = read_count(in, "bounding entities", 2);
          for (uint64_t k = 0; k < bounding; ++k) in.to_integer(in.next_token(), "bounding entity");
        }
      }
  }
  void elements41() {
    const uint64_t blocks = read_count(in, "element blocks", 8);
    read_count(in, "elements", 4);
    in.to_integer(in.next_token(), "min element tag");
    in.to_integer(in.next_token(), "max element tag");
    for (uint64_t b = 0; b < blocks; ++b) {
      const int64_t dim = in.to_integer(in.next_token(), "entity dimension", 0, 3);
      const int64_t entity = in.to_integer(in.next_token(), "entity tag");
      const int64_t type = in.to_integer(in.next_token(), "element type");
      const uint64_t k = read_count(in, "elements in block", 4);
      int64_t label = entity;
      if (dim == 3)
        if (const auto it = volume_physical.find(entity); it != volume_physical.end()) label = it->second;
      for (uint64_t e = 0; e < k; ++e) element(in.to_integer(in.next_token(), "element tag"), type, label);
    }
  }
  void nodes22() {
    const uint64_t count = read_count(in, "nodes", 8);
    std::vector<std::pair<int64_t, std::array<double, 3>>> nodes;
    // Tags first (the table needs the largest), so read the block once into a list bounded by the file.
    nodes.reserve(count);
    int64_t max_tag = 0;
    for (uint64_t i = 0; i < count; ++i) {
      const int64_t t = in.to_integer(in.next_token(), "node tag", 1, INT64_MAX);
      std::array<double, 3> p{};
      for (double& x : p) x = in.to_double(in.next_token(), "a coordinate");
      nodes.push_back({t, p});
      max_tag = std::max(max_tag, t);
    }
    node_table(static_cast<uint64_t>(max_tag), count);
    for (const auto& [t, p] : nodes) add_node(t, p[0], p[1], p[2]);
  }
  void elements22() {
    const uint64_t count = read_count(in, "elements", 8);
    for (uint64_t e = 0; e < count; ++e) {
      const int64_t tag = in.to_integer(in.next_token(), "element tag");
      const int64_t type = in.to_integer(in.next_token(), "element type");
      const int64_t ntags = in.to_integer(in.next_token(), "number of tags", 0, 64);
      int64_t physical = 0, elementary = 0;
      for (int64_t k = 0; k < ntags; ++k) {
        const int64_t v = in.to_integer(in.next_token(), "tag");
        if (k == 0) physical = v;
        if (k == 1) elementary = v;
      }
      element(tag, type, type == 4 ? physical : elementary);
    }
  }

  void finish() {
    auto by_tag = [](const Element& a, const Element& b) { return a.tag < b.tag; };
    std::stable_sort(tets.begin(), tets.end(), by_tag);
    std::stable_sort(triangles.begin(), triangles.end(), by_tag);
    for (const auto& e : tets) {
      for (uint32_t v : file_order(e.v.data())) m.tetrahedra.push_back(v);
      if (e.label < 0 || e.label > INT32_MAX) in.fail(InputErrorKind::Syntax, "region " + std::to_string(e.label) + " of element " + std::to_string(e.tag));
      m.regions.push_back(e.label == 0 ? 0 : static_cast<int32_t>(e.label - 1));
    }
    for (const auto& e : triangles) {
      m.boundary.insert(m.boundary.end(), e.v.begin(), e.v.begin() + 3);
      m.boundary_tags.push_back(e.label == kUntaggedSurface || e.label <= 0 || e.label > INT64_C(0xFFFFFFFF) ? kNone : static_cast<uint32_t>(e.label - 1));
    }
    m.num_input_points = static_cast<uint32_t>(m.num_points());
  }
};

}  // namespace

VolumeMesh read_gmsh(std::string_view bytes, const std::string& file) {
  TextScanner in(bytes, file, '\0');
  Reader r{in, {}, {}, {}, {}, {}};
  bool version2 = false, have_format = false, have_nodes = false;
  for (std::string_view key = in.next_token(); !key.empty(); key = in.next_token()) {
    if (key == "$MeshFormat") {
      const auto v = in.next_token();
      if (v != "4.1" && v != "2.2") in.fail(InputErrorKind::Unsupported, "msh version " + std::string(v.substr(0, 20)) + " (4.1 and 2.2 are read)");
      version2 = v == "2.2";
      if (in.to_integer(in.next_token(), "file type") != 0) in.fail(InputErrorKind::Unsupported, "binary .msh (ascii is read)");
      in.to_integer(in.next_token(), "data size");
      have_format = true;
      r.expect_end("MeshFormat");
    } else if (!have_format) {
      in.fail(InputErrorKind::Syntax, "the file does not start with $MeshFormat");
    } else if (key == "$Entities" && !version2) {
      r.entities41();
      r.expect_end("Entities");
    } else if (key == "$Nodes") {
      if (have_nodes) in.fail(InputErrorKind::Syntax, "a second $Nodes section");
      have_nodes = true;
      version2 ? r.nodes22() : r.nodes41();
      r.expect_end("Nodes");
    } else if (key == "$Elements") {
      if (!have_nodes) in.fail(InputErrorKind::Syntax, "$Elements before $Nodes");
      version2 ? r.elements22() : r.elements41();
      r.expect_end("Elements");
    } else if (key.starts_with("$") && !key.starts_with("$End")) {
      // Other sections ($PhysicalNames, $NodeData, ...): read past to their end.
      const std::string end = "$End" + std::string(key.substr(1));
      std::string_view t;
      do t = in.next_token();
      while (!t.empty() && t != end);
      if (t.empty()) in.fail(InputErrorKind::Truncated, "no " + end);
    } else {
      in.fail(InputErrorKind::Syntax, "expected a section ($Name), found '" + std::string(key.substr(0, 40)) + "'");
    }
  }
  if (!have_nodes) fail(InputErrorKind::Truncated, file, Location::none(), "no $Nodes section");
  r.finish();
  return std::move(r.m);
}

}  // namespace sweepcdt::io::detail
