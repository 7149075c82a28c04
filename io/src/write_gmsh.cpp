// Gmsh .msh ascii, version 4.1 (Gmsh's default since 4.1) or 2.2 (older readers: FEniCS dolfin-convert,
// many solvers).
//
// Geometry entities stand for what a CAD model would give: volume entity r+1 per region (physical
// group (3, r+1) "region_<r+1>"), surface entity tag+1 per boundary tag (all in physical group
// (2, 1) "boundary"; entity 2147483647 holds triangles without a tag). Elements: tetrahedra
// 1..t (type 4, positive volume) in mesh order, then boundary triangles t+1..t+b (type 2,
// counterclockwise seen from outside); nodes 1..n. Version 4.1 puts every node in the block of the
// first volume entity (no node is classified on a surface: the mesh is not a parametrised CAD mesh).
#include <algorithm>
#include <limits>
#include <map>

#include "volume_mesh_formats.h"

namespace sweepcdt::io::detail {
namespace {

constexpr int64_t kUntaggedSurface = std::numeric_limits<int32_t>::max();
constexpr int kBoundaryPhysical = 1;

int64_t surface_entity(uint32_t tag) { return tag == kNone ? kUntaggedSurface : int64_t{tag} + 1; }

struct Entity {
  std::vector<std::size_t> elements;  // indices into tetrahedra or boundary triangles
  std::array<double, 6> box{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  void grow(const VolumeMesh& m, uint32_t v) {
    for (int k = 0; k < 3; ++k) {
      box[k] = std::min(box[k], m.points[3 * std::size_t{v} + k]);
      box[3 + k] = std::max(box[3 + k], m.points[3 * std::size_t{v} + k]);
    }
  }
};

void line(std::string& out, std::initializer_list<int64_t> values) {
  bool first = true;
  for (int64_t v : values) {
    if (!first) out += ' ';
    append_int(out, v);
    first = false;
  }
  out += '\n';
}

void physical_names(std::string& out, const std::map<int64_t, Entity>& volumes, bool with_boundary) {
  out += "$PhysicalNames\n";
  append_int(out, static_cast<int64_t>(volumes.size() + (with_boundary ? 1 : 0)));
  out += '\n';
  for (const auto& [tag, e] : volumes) out += "3 " + std::to_string(tag) + " \"region_" + std::to_string(tag) + "\"\n";
  if (with_boundary) out += "2 " + std::to_string(kBoundaryPhysical) + " \"boundary\"\n";
  out += "$EndPhysicalNames\n";
}

void tet_line(std::string& out, const VolumeMesh& m, std::size_t t) {
  for (uint32_t v : file_order(&m.tetrahedra[4 * t])) {
    out += ' ';
    append_int(out, int64_t{v} + 1);
  }
  out += '\n';
}

void triangle_line(std::string& out, const VolumeMesh& m, std::size_t b) {
  for (int k = 0; k < 3; ++k) {
    out += ' ';
    append_int(out, int64_t{m.boundary[3 * b + k]} + 1);
  }
  out += '\n';
}

void version2(const VolumeMesh& m, const std::map<int64_t, Entity>& volumes, TextOut& o) {
  std::string& out = o.text;
  out += "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  physical_names(out, volumes, m.num_boundary() > 0);
  out += "$Nodes\n";
  append_int(out, static_cast<int64_t>(m.num_points()));
  out += '\n';
  for (std::size_t i = 0; i < m.num_points(); ++i) {
    append_int(out, static_cast<int64_t>(i) + 1);
    out += ' ';
    append_point(out, m, i);
    out += '\n';
    o.spill();
  }
  out += "$EndNodes\n$Elements\n";
  append_int(out, static_cast<int64_t>(m.num_tetrahedra() + m.num_boundary()));
  out += '\n';
  // id type number-of-tags physical elementary nodes...
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t) {
    append_int(out, static_cast<int64_t>(t) + 1);
    out += " 4 2 " + std::to_string(int64_t{m.regions[t]} + 1) + " " + std::to_string(int64_t{m.regions[t]} + 1);
    tet_line(out, m, t);
    o.spill();
  }
  for (std::size_t b = 0; b < m.num_boundary(); ++b) {
    append_int(out, static_cast<int64_t>(m.num_tetrahedra() + b) + 1);
    out += " 2 2 " + std::to_string(kBoundaryPhysical) + " " + std::to_string(surface_entity(m.boundary_tags[b]));
    triangle_line(out, m, b);
    o.spill();
  }
  out += "$EndElements\n";
}

void entity_line(std::string& out, int64_t tag, const Entity& e, int64_t physical) {
  append_int(out, tag);
  for (double x : e.box) {
    out += ' ';
    append_double(out, e.elements.empty() ? 0.0 : x);  // an empty entity has no box
  }
  out += " 1 " + std::to_string(physical) + " 0\n";  // one physical tag, no bounding entities
}

void version41(const VolumeMesh& m, const std::map<int64_t, Entity>& volumes, const std::map<int64_t, Entity>& surfaces, TextOut& o) {
  const std::size_t n = m.num_points(), t = m.num_tetrahedra(), b = m.num_boundary();
  std::string& out = o.text;
  out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  physical_names(out, volumes, b > 0);
  out += "$Entities\n";
  line(out, {0, 0, static_cast<int64_t>(surfaces.size()), static_cast<int64_t>(volumes.size())});
  for (const auto& [tag, e] : surfaces) entity_line(out, tag, e, kBoundaryPhysical);
  for (const auto& [tag, e] : volumes) entity_line(out, tag, e, tag);
  out += "$EndEntities\n$Nodes\n";
  if (n == 0) {
    out += "0 0 0 0\n";
  } else {
    line(out, {1, static_cast<int64_t>(n), 1, static_cast<int64_t>(n)});
    line(out, {3, volumes.empty() ? 1 : volumes.begin()->first, 0, static_cast<int64_t>(n)});
    for (std::size_t i = 0; i < n; ++i) {
      line(out, {static_cast<int64_t>(i) + 1});
      o.spill();
    }
    for (std::size_t i = 0; i < n; ++i) {
      append_point(out, m, i);
      out += '\n';
      o.spill();
    }
  }
  out += "$EndNodes\n$Elements\n";
  // Blocks only for entities with elements (an empty volume holds the nodes of a mesh without any).
  const auto nonempty = std::count_if(volumes.begin(), volumes.end(), [](const auto& v) { return !v.second.elements.empty(); });
  line(out, {static_cast<int64_t>(nonempty + surfaces.size()), static_cast<int64_t>(t + b), t + b ? 1 : 0, static_cast<int64_t>(t + b)});
  for (const auto& [tag, e] : volumes) {
    if (e.elements.empty()) continue;
    line(out, {3, tag, 4, static_cast<int64_t>(e.elements.size())});
    for (std::size_t k : e.elements) {
      append_int(out, static_cast<int64_t>(k) + 1);
      tet_line(out, m, k);
      o.spill();
    }
  }
  for (const auto& [tag, e] : surfaces) {
    line(out, {2, tag, 2, static_cast<int64_t>(e.elements.size())});
    for (std::size_t k : e.elements) {
      append_int(out, static_cast<int64_t>(t + k) + 1);
      triangle_line(out, m, k);
      o.spill();
    }
  }
  out += "$EndElements\n";
}

}  // namespace

void gmsh_text(const VolumeMesh& m, bool v2, TextOut& o) {
  std::map<int64_t, Entity> volumes, surfaces;  // by entity tag, so the file lists them in order
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t) {
    Entity& e = volumes[int64_t{m.regions[t]} + 1];
    e.elements.push_back(t);
    for (int k = 0; k < 4; ++k) e.grow(m, m.tetrahedra[4 * t + k]);
  }
  for (std::size_t b = 0; b < m.num_boundary(); ++b) {
    Entity& e = surfaces[surface_entity(m.boundary_tags[b])];
    e.elements.push_back(b);
    for (int k = 0; k < 3; ++k) e.grow(m, m.boundary[3 * b + k]);
  }
  // Version 4.1 classifies every node on an entity: points without tetrahedra need a volume too.
  if (!v2 && volumes.empty() && m.num_points() > 0) volumes[1];
  if (v2) version2(m, volumes, o);
  else version41(m, volumes, surfaces, o);
}

}  // namespace sweepcdt::io::detail
