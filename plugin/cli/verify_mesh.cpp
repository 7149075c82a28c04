// How a volume mesh is checked against its surface, exactly, without trusting anything the mesh
// file says beyond its points and tetrahedra:
//
// 1. The input's welded points come first in the mesh, bit for bit (the writers promise this).
// 2. Steiner points. `--steiner auto` splits input edges (sweepcdt/steiner_point.h: at a power of
//    two from an input vertex, or at a + (b - a)/2) in double arithmetic, so they lie on the edge
//    only up to rounding — an exact "point on triangle" test would reject correct meshes, and any
//    tolerance would be a guess. Instead each Steiner point (in order) must be reproduced bit for
//    bit by that construction from two points already known to lie on one edge of an input triangle
//    — or, for the few points that split a fold inside a triangle (core/src/steiner/refine.cpp), on
//    that triangle. Points exactly coplanar with their triangle are counted separately.
// 3. The refined surface: the boundary facets of the tetrahedra (facets of one tetrahedron). Each
//    must have all three vertices on one input triangle (2.), with the tetrahedron on the side that
//    the input's exterior notation says is inside, and every input triangle must be covered by as
//    many such facets as a triangulation of it with its points has (b + 2i - 2: b points on its
//    edges, i inside), forming one patch bounded by its edges. Without Steiner points the input PLC
//    itself is used for validate() instead: exact.
//    The file's own boundary triangles (what solvers read) must be exactly these facets, oriented
//    outward, tagged with their input triangle.
// 4. validate() of the tetrahedra against that PLC: topology, orientation, every constraint a
//    facet, the domain covered (exact volume sums), every interior facet locally Delaunay — under
//    the first of cdt()'s perturbation orders that makes it so (paper §6; only without Steiner
//    points, which cdt() makes under the vertex-id order alone).
#include "verify_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "sweepcdt/perturbation_order.h"
#include "sweepcdt/predicates.h"
#include "sweepcdt/steiner_point.h"
#include "sweepcdt/validate.h"

namespace sweepcdt::cli {
namespace {

constexpr std::size_t kProblemsShown = 10;

class Problems {
 public:
  explicit Problems(MeshVerification& v) : v_(v) {}
  void add(const std::string& text) {
    if (v_.problems.size() < kProblemsShown) v_.problems.push_back(text);
    ++v_.total_problems;
  }

 private:
  MeshVerification& v_;
};

std::string point_text(const double* p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", p[0], p[1], p[2]);
  return buf;
}

std::string ids_text(const uint32_t* ids, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) {
    if (i) s += ' ';
    s += std::to_string(ids[i]);
  }
  return s;
}

bool same_point(const double* a, const double* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

// The construction of --steiner auto (sweepcdt/steiner_point.h), operation for operation: a is the
// end with the smaller id.
bool is_split_point(const double* s, const double* a, bool a_is_input, const double* b, bool b_is_input) {
  double x[3];
  segment_split_point(a, a_is_input, b, b_is_input, x);
  return s[0] == x[0] && s[1] == x[1] && s[2] == x[2];
}

struct OnTriangle {
  uint32_t point;
  uint8_t edges;  // bit e: on edge e = (v_e, v_{e+1}) of the triangle; 0: inside
};

using Facet = std::array<uint32_t, 3>;

// The axis of the largest component of triangle abc's normal (floating point: it only picks the least
// distorted projection; the orientations in it are exact).
int dominant_axis(const double* a, const double* b, const double* c) {
  int best = 0;
  double largest = -1;
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const double n = std::abs((b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]));
    if (n > largest) largest = n, best = axis;
  }
  return best;
}

// The input triangles whose closed bounding box holds a point (a split point of two points of a
// triangle stays in its box, rounding included: rounding is monotone). A uniform grid of about one
// cell per triangle, so that checking many Steiner points is not O(points x triangles).
class TriangleGrid {
 public:
  explicit TriangleGrid(const Plc<3>& plc) : box_(plc.num_simplices()) {
    lo_.fill(std::numeric_limits<double>::infinity());
    std::array<double, 3> hi;
    hi.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t j = 0; j < box_.size(); ++j)
      for (int c = 0; c < 3; ++c) {
        const double a = plc.point(plc.simplex(j)[0])[c], b = plc.point(plc.simplex(j)[1])[c], d = plc.point(plc.simplex(j)[2])[c];
        box_[j][c] = std::min({a, b, d});
        box_[j][3 + c] = std::max({a, b, d});
        lo_[c] = std::min(lo_[c], box_[j][c]);
        hi[c] = std::max(hi[c], box_[j][3 + c]);
      }
    cells_ = std::max(1, static_cast<int>(std::cbrt(static_cast<double>(box_.size()))));
    for (int c = 0; c < 3; ++c) scale_[c] = hi[c] > lo_[c] ? cells_ / (hi[c] - lo_[c]) : 0.0;
    grid_.resize(std::size_t(cells_) * cells_ * cells_);
    for (uint32_t j = 0; j < box_.size(); ++j) {
      std::array<int, 3> a, b;
      for (int c = 0; c < 3; ++c) a[c] = cell(c, box_[j][c]), b[c] = cell(c, box_[j][3 + c]);
      for (int x = a[0]; x <= b[0]; ++x)
        for (int y = a[1]; y <= b[1]; ++y)
          for (int z = a[2]; z <= b[2]; ++z) grid_[index(x, y, z)].push_back(j);  // ascending j in every cell
    }
  }
  const std::vector<uint32_t>& near(const double* p) const { return grid_[index(cell(0, p[0]), cell(1, p[1]), cell(2, p[2]))]; }
  bool box_holds(uint32_t j, const double* p) const {
    for (int c = 0; c < 3; ++c)
      if (p[c] < box_[j][c] || p[c] > box_[j][3 + c]) return false;
    return true;
  }

 private:
  // Monotone in x, so a box holding p overlaps p's cell.
  int cell(int c, double x) const {
    const double f = std::floor((x - lo_[c]) * scale_[c]);
    return f < 0 ? 0 : f >= cells_ ? cells_ - 1 : static_cast<int>(f);
  }
  std::size_t index(int x, int y, int z) const { return (std::size_t(x) * cells_ + y) * cells_ + z; }

  std::vector<std::array<double, 6>> box_;
  std::array<double, 3> lo_, scale_;
  int cells_ = 1;
  std::vector<std::vector<uint32_t>> grid_;
};

// 3a. The pieces of each input triangle form one patch: every edge inside the patch is shared by
// exactly two pieces, and every edge of one piece only runs along an edge of the triangle (both
// ends on that edge). With the counts of 3, this makes the patch a triangulated disc bounded by
// the triangle's edges: the triangle is covered, without gaps or folds.
void check_patches(const std::map<Facet, std::pair<Facet, uint32_t>>& on_input, const std::vector<std::vector<OnTriangle>>& on,
                   const Plc<3>& input, Problems& problems) {
  std::vector<std::array<uint32_t, 3>> edges;  // (input triangle, smaller id, larger id)
  for (const auto& [key, entry] : on_input)
    for (int k = 0; k < 3; ++k) edges.push_back({entry.second, std::min(key[k], key[(k + 1) % 3]), std::max(key[k], key[(k + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  const auto edge_bits = [&](uint32_t j, uint32_t point) {
    for (const OnTriangle& p : on[j])
      if (p.point == point) return p.edges;
    return uint8_t{0};
  };
  for (std::size_t a = 0, b; a < edges.size(); a = b) {
    for (b = a + 1; b < edges.size() && edges[b] == edges[a]; ++b) {
    }
    const auto [j, p, q] = edges[a];
    const std::string name = "edge (" + std::to_string(p) + " " + std::to_string(q) + ") of the pieces of input triangle " + std::to_string(j) +
                             " (" + ids_text(input.simplex(j), 3) + ")";
    if (b - a > 2) problems.add(name + " is shared by " + std::to_string(b - a) + " of them");
    if (b - a == 1 && (edge_bits(j, p) & edge_bits(j, q)) == 0) problems.add(name + " bounds the patch but does not run along an edge of the triangle");
  }
}

bool same_rotation(const Facet& a, const Facet& b) {
  return a == b || a == Facet{b[1], b[2], b[0]} || a == Facet{b[2], b[0], b[1]};
}

// 3b. What solvers read as the boundary — the file's boundary triangles and their tags — must be
// the tetrahedra's boundary facets, counterclockwise seen from outside, each tagged with the input
// triangle it lies on. `on_input`: the boundary facets found from the tetrahedra.
void check_file_boundary(const io::VolumeMesh& mesh, const std::map<Facet, std::pair<Facet, uint32_t>>& on_input, Problems& problems,
                         MeshVerification& v) {
  v.file_boundary = mesh.num_boundary() > 0;
  if (!v.file_boundary) return;
  // Formats without face tags (Abaqus) give kNone: nothing to compare.
  const bool tagged = mesh.boundary_tags.size() == mesh.num_boundary() &&
                      std::any_of(mesh.boundary_tags.begin(), mesh.boundary_tags.end(), [](uint32_t t) { return t != kNone; });
  v.file_tags = tagged;
  std::size_t listed = 0;
  for (std::size_t k = 0; k < mesh.num_boundary(); ++k) {
    const Facet g{mesh.boundary[3 * k], mesh.boundary[3 * k + 1], mesh.boundary[3 * k + 2]};
    Facet key = g;
    std::sort(key.begin(), key.end());
    const auto it = on_input.find(key);
    const std::string name = "the file's boundary triangle " + std::to_string(k) + " (" + ids_text(g.data(), 3) + ")";
    if (it == on_input.end()) {
      problems.add(name + " is not a boundary facet of the tetrahedra");
      continue;
    }
    ++listed;
    if (!same_rotation(g, it->second.first)) problems.add(name + " is oriented inward (clockwise seen from outside)");
    if (tagged && mesh.boundary_tags[k] != it->second.second)
      problems.add(name + " is tagged " + std::to_string(mesh.boundary_tags[k]) + " but lies on input triangle " + std::to_string(it->second.second));
  }
  if (listed < on_input.size())
    problems.add(std::to_string(on_input.size() - listed) + " boundary facets of the tetrahedra are missing from the file's boundary triangles");
}

}  // namespace

MeshVerification verify_mesh(const Plc<3>& input, const io::VolumeMesh& mesh) {
  MeshVerification v;
  Problems problems(v);
  const std::size_t n = input.num_points(), total = mesh.num_points(), m = input.num_simplices();

  // 1. Input points.
  v.steiner_points = total > n ? total - n : 0;
  if (total < n) {
    problems.add("the mesh has " + std::to_string(total) + " vertices, fewer than the input's " + std::to_string(n));
    return v;
  }
  for (uint32_t i = 0; i < n; ++i)
    if (!same_point(mesh.points.data() + 3 * std::size_t{i}, input.point(i))) {
      v.input_points_moved = true;
      problems.add("vertex " + std::to_string(i) + " is " + point_text(mesh.points.data() + 3 * std::size_t{i}) + " in the mesh but " +
                   point_text(input.point(i)) + " in the input");
    }
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    if (mesh.tetrahedra[t] >= total) {
      problems.add("tetrahedron " + std::to_string(t / 4) + " names vertex " + std::to_string(mesh.tetrahedra[t]) + ", which does not exist");
      break;
    }
  if (!v.ok()) return v;

  // 2. Steiner points, in the order they were made.
  std::vector<std::vector<OnTriangle>> on(m);  // per input triangle: the points known to lie on it
  std::vector<std::vector<uint32_t>> triangles_of(total);  // per point: the input triangles it lies on
  for (uint32_t j = 0; j < m; ++j)
    for (int k = 0; k < 3; ++k) {
      const uint32_t p = input.simplex(j)[k];
      on[j].push_back({p, static_cast<uint8_t>((1u << k) | (1u << ((k + 2) % 3)))});
      triangles_of[p].push_back(j);
    }
  const TriangleGrid grid(input);
  for (uint32_t s = static_cast<uint32_t>(n); s < total; ++s) {
    const double* ps = mesh.points.data() + 3 * std::size_t{s};
    for (const uint32_t j : grid.near(ps)) {
      if (!grid.box_holds(j, ps)) continue;
      const auto& known = on[j];
      bool found = false;
      uint8_t edges = 0;
      // An edge's split point; else, second pass, a split point inside the triangle (a fold that
      // rounding made a segment: core/src/steiner/refine.cpp), of two of its points on no common edge.
      for (int pass = 0; pass < 2 && !found; ++pass)
        for (std::size_t a = 0; a < known.size() && !found; ++a)
          for (std::size_t b = 0; b < known.size() && !found; ++b)
            if (known[a].point < known[b].point && (pass == 1 || (known[a].edges & known[b].edges)) &&
                is_split_point(ps, mesh.points.data() + 3 * std::size_t{known[a].point}, known[a].point < n,
                               mesh.points.data() + 3 * std::size_t{known[b].point}, known[b].point < n)) {
              found = true;
              edges = known[a].edges & known[b].edges;
            }
      if (!found) continue;
      on[j].push_back({s, edges});
      triangles_of[s].push_back(j);
    }
    if (triangles_of[s].empty()) {
      problems.add("Steiner point " + std::to_string(s) + " " + point_text(ps) + " is not the split point of two points of one input triangle");
      continue;
    }
    const uint32_t* t = input.simplex(triangles_of[s].front());
    if (predicates::orient<3>({input.point(t[0]), input.point(t[1]), input.point(t[2]), ps}) == predicates::Sign::Zero) ++v.steiner_exactly_on;
  }
  if (!v.ok()) return v;

  // 3. The boundary of the tetrahedra, each facet with the tetrahedron on its positive side.
  std::map<Facet, std::pair<int, Facet>> facets;  // sorted ids -> (count, oriented facet)
  std::map<Facet, uint32_t> apex;                 // sorted ids -> the tetrahedron's other vertex
  for (std::size_t t = 0; t < mesh.num_tetrahedra(); ++t) {
    const uint32_t* q = mesh.tetrahedra.data() + 4 * t;
    for (int i = 0; i < 4; ++i) {
      Facet f{q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]};
      const auto sign = predicates::orient<3>({mesh.points.data() + 3 * std::size_t{f[0]}, mesh.points.data() + 3 * std::size_t{f[1]},
                                               mesh.points.data() + 3 * std::size_t{f[2]}, mesh.points.data() + 3 * std::size_t{q[i]}});
      if (sign == predicates::Sign::Negative) std::swap(f[1], f[2]);
      Facet key = f;
      std::sort(key.begin(), key.end());
      auto& entry = facets[key];
      if (entry.first++ == 0) entry.second = f;
      apex[key] = q[i];
    }
  }
  Plc<3> refined;
  refined.points = mesh.points;
  std::vector<std::size_t> pieces(m, 0);
  std::map<Facet, std::pair<Facet, uint32_t>> on_input;  // sorted ids -> (oriented boundary facet, input triangle)
  for (const auto& [key, entry] : facets) {
    if (entry.first != 1) continue;  // interior (2) or over-shared (validate() reports it)
    ++v.boundary_triangles;
    const Facet& f = entry.second;
    // The input triangles all three vertices lie on.
    std::vector<uint32_t> common = triangles_of[f[0]];
    for (int k = 1; k < 3; ++k) {
      std::vector<uint32_t> next;
      std::set_intersection(common.begin(), common.end(), triangles_of[f[k]].begin(), triangles_of[f[k]].end(), std::back_inserter(next));
      common.swap(next);
    }
    if (common.empty()) {
      problems.add("boundary triangle (" + ids_text(f.data(), 3) + ") does not lie on an input triangle");
      continue;
    }
    const uint32_t j = common.front();
    const uint32_t* t = input.simplex(j);
    // The tetrahedron is on f's positive side. Rounded Steiner points fold a triangle's pieces by a
    // rounding error, so an apex can sit on either side of the input triangle's exact plane: compare
    // orientations instead, in a projection along the triangle's normal (exact; pieces do not
    // degenerate in it), where f's orientation says on which side of the triangle its tetrahedron is.
    int drop = dominant_axis(input.point(t[0]), input.point(t[1]), input.point(t[2]));
    if (predicates::orient_projected<3>({input.point(t[0]), input.point(t[1]), input.point(t[2])}, drop) == predicates::Sign::Zero) drop = (drop + 1) % 3;
    if (predicates::orient_projected<3>({input.point(t[0]), input.point(t[1]), input.point(t[2])}, drop) == predicates::Sign::Zero) drop = (drop + 1) % 3;
    const auto piece = predicates::orient_projected<3>({mesh.points.data() + 3 * std::size_t{f[0]}, mesh.points.data() + 3 * std::size_t{f[1]},
                                                        mesh.points.data() + 3 * std::size_t{f[2]}}, drop);
    const auto whole = predicates::orient_projected<3>({input.point(t[0]), input.point(t[1]), input.point(t[2])}, drop);
    const auto side = piece == whole ? predicates::Sign::Positive : predicates::Sign::Negative;
    const auto inside = input.exterior_of(j) == ExteriorSide::Negative ? predicates::Sign::Positive : predicates::Sign::Negative;
    if (piece == predicates::Sign::Zero || side != inside)
      problems.add("boundary triangle (" + ids_text(f.data(), 3) + ") on input triangle " + std::to_string(j) +
                   " has its tetrahedron on the outside of the surface");
    ++pieces[j];
    on_input.emplace(key, std::make_pair(f, j));
    refined.simplices.insert(refined.simplices.end(), f.begin(), f.end());
    refined.exterior.push_back(ExteriorSide::Negative);
    refined.tags.push_back(j);
  }
  for (uint32_t j = 0; j < m; ++j) {
    std::size_t b = 0, i = 0;
    for (const auto& p : on[j]) (p.edges ? b : i) += 1;
    const std::size_t expected = b + 2 * i - 2;
    if (pieces[j] != expected)
      problems.add("input triangle " + std::to_string(j) + " (" + ids_text(input.simplex(j), 3) + ") is covered by " + std::to_string(pieces[j]) +
                   " boundary triangles; a triangulation of it with its " + std::to_string(b + i) + " points has " + std::to_string(expected));
  }
  check_patches(on_input, on, input, problems);
  check_file_boundary(mesh, on_input, problems, v);
  if (!v.ok()) return v;

  // 4. validate(): against the input itself when nothing was added.
  Triangulation<3> tri;
  tri.points = mesh.points;
  tri.num_input_points = static_cast<uint32_t>(total);
  tri.simplices = mesh.tetrahedra;
  if (mesh.regions.size() == mesh.num_tetrahedra()) tri.regions = mesh.regions;
  compute_neighbors(tri);
  const bool exact_input = v.steiner_points == 0;
  if (!exact_input) {
    // Pieces of different triangles must not cross (find_problems is exact).
    for (const auto& p : find_problems(refined, kProblemsShown)) problems.add("refined surface: " + p.message);
    if (!v.ok()) return v;
  }
  ValidationReport report = validate(tri, exact_input ? input : refined);
  // Paper §6: cdt() tries further perturbation orders when the vertex-id order leaves the PLC as
  // given without a CDT (sweepcdt/perturbation_order.h); so does this, when only the local Delaunay
  // test failed — the one check the order can change. Steiner points come with the vertex-id order.
  for (int order = 1; exact_input && order < kPerturbationOrders && report.counts.size() == 1 && report.count("locally-delaunay"); ++order) {
    tri.perturbation_rank = perturbation_rank(input, order);
    ValidationReport in_order = validate(tri, input);
    if (in_order.ok()) {
      report = std::move(in_order);
      v.perturbation_order = order;
    }
  }
  v.validated = true;
  for (const auto& f : report.failures) problems.add(f.check + ": " + f.detail);
  // failures holds the first few of each check; counts has them all.
  std::size_t all = 0;
  for (const auto& [check, count] : report.counts) all += count;
  if (all > report.failures.size()) v.total_problems += all - report.failures.size();
  return v;
}

}  // namespace sweepcdt::cli
