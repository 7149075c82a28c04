// verify_cdt() (sweepcdt/verify_cdt.h). How a volume mesh is checked against its surface, exactly, without trusting anything the mesh
// file says beyond its points and tetrahedra:
//
// 1. The input's welded points come first in the mesh, bit for bit (the writers promise this).
// 2. The input's facets (surface_facets.h): with --facets triangles each input triangle; with
//    --facets coplanar the polygons of edge-adjacent, exactly coplanar triangles, grouped here by
//    the documented rule. Steiner points (surface_points.h): `--steiner auto` splits segments
//    (sweepcdt/steiner_point.h: the rounded a + t (b - a)) in double arithmetic, so they lie on the
//    segment only up to rounding — an exact "point on edge" test would reject correct meshes, and
//    any tolerance would be a guess. Instead each Steiner point (in order) must be exactly that
//    construction, for some t, from two neighbouring points on a facet boundary edge — or, for the
//    few points that split a fold inside a facet (core/src/steiner/refine.cpp), from two points of
//    that facet. Points exactly coplanar with
//    their facet are counted separately.
// 3. The refined surface (verify_facet_patches.h): the boundary facets of the tetrahedra (facets of
//    one tetrahedron). Each must have all three vertices on one facet, with the tetrahedron on the
//    side that the input's exterior notation says is inside, and each facet's pieces must tile it:
//    every inner edge shared by two pieces once each way, the other edges exactly the facet's
//    boundary split at its points, every point of the facet a vertex. Without Steiner points and
//    with --facets triangles the input PLC itself is used for validate() instead: exact.
//    The file's own boundary triangles (what solvers read) must be exactly these facets, oriented
//    outward, tagged with the face id `mesh` writes: the input triangle, or the coplanar facet's
//    first input triangle.
// 4. validate() of the tetrahedra against that PLC: topology, orientation, every constraint a
//    facet, the domain covered (exact volume sums), every interior facet locally Delaunay — under
//    the first of cdt()'s perturbation orders that makes it so (paper §6; only without Steiner
//    points, which cdt() makes under the vertex-id order alone).
// A mesh made with --facets triangles is also accepted with --facets coplanar where the format has
// no face ids: its Steiner points on edges inside a facet are fold-like points of that facet, its
// pieces tile the facet, and a CDT of its pieces is a CDT of the polygons (the same points, the same
// surface blocking visibility). Its face ids name input triangles, not facets, so it fails on them.
#include "sweepcdt/verify_cdt.h"

#include <algorithm>
#include <array>

#include "../facets.h"
#include "../ids_text.h"
#include "../refined_check.h"
#include "problems.h"
#include "surface_facets.h"
#include "surface_points.h"
#include "sweepcdt/perturbation_order.h"
#include "sweepcdt/predicates.h"
#include "sweepcdt/validate.h"
#include "verify_facet_patches.h"

namespace sweepcdt {
namespace {

using detail::Problems;
using detail::SurfaceFacets;
using detail::SurfacePoints;
using detail::Triangle;
using detail::point_text;

bool same_point(const double* a, const double* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

bool same_rotation(const Triangle& a, const Triangle& b) {
  return a == b || a == Triangle{b[1], b[2], b[0]} || a == Triangle{b[2], b[0], b[1]};
}

// The boundary facets of the tetrahedra (facets of exactly one), each oriented with its tetrahedron
// on its positive side, in the order of their sorted ids. Over-shared facets are validate()'s to report.
std::vector<Triangle> boundary_of(const Triangulation<3>& tets) {
  const auto facets = detail::sorted_facets(tets);
  std::vector<Triangle> boundary;
  detail::for_each_facet_group<3>(facets, [&](std::size_t begin, std::size_t end) {
    if (end - begin != 1) return;
    const uint32_t* q = tets.simplex(facets[begin].simplex);
    const uint32_t i = facets[begin].local;
    Triangle f{q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]};
    if (predicates::orient<3>({tets.point(f[0]), tets.point(f[1]), tets.point(f[2]), tets.point(q[i])}) == predicates::Sign::Negative)
      std::swap(f[1], f[2]);
    boundary.push_back(f);
  });
  return boundary;
}

// The boundary facets of the tetrahedra by their sorted ids, ascending: (sorted ids, (the facet
// oriented with its tetrahedron positive, its input facet)).
using Pieces = std::vector<std::pair<Triangle, std::pair<Triangle, uint32_t>>>;

// What solvers read as the boundary — the file's boundary triangles and their tags — must be the
// tetrahedra's boundary facets (`pieces`), counterclockwise seen from outside, each tagged with its
// face id.
void check_file_boundary(const TetMeshView& mesh, const Pieces& pieces,
                         const Plc<3>& input, const SurfaceFacets& facets, Problems& problems, MeshVerification& v) {
  v.file_boundary = mesh.num_boundary() > 0;
  if (!v.file_boundary) return;
  // Formats without face tags (Abaqus) give kNone: nothing to compare.
  const bool tagged = mesh.boundary_tags.size() == mesh.num_boundary() &&
                      std::any_of(mesh.boundary_tags.begin(), mesh.boundary_tags.end(), [](uint32_t t) { return t != kNone; });
  v.file_tags = tagged;
  std::size_t listed = 0;
  for (std::size_t k = 0; k < mesh.num_boundary(); ++k) {
    const Triangle g{mesh.boundary[3 * k], mesh.boundary[3 * k + 1], mesh.boundary[3 * k + 2]};
    Triangle key = g;
    std::sort(key.begin(), key.end());
    const auto it = std::lower_bound(pieces.begin(), pieces.end(), key, [](const auto& piece, const Triangle& k) { return piece.first < k; });
    const std::string name = "the file's boundary triangle " + std::to_string(k) + " " + detail::ids_text(g.data(), 3);
    if (it == pieces.end() || it->first != key) {
      problems.add(name + " is not a boundary facet of the tetrahedra");
      continue;
    }
    ++listed;
    if (!same_rotation(g, it->second.first)) problems.add(name + " is oriented inward (clockwise seen from outside)");
    const uint32_t face_id = facets.first_triangle(it->second.second);
    if (tagged && mesh.boundary_tags[k] != face_id)
      problems.add(name + " is tagged " + std::to_string(mesh.boundary_tags[k]) + " but lies on " + facets.name(it->second.second, input) +
                   ": face id " + std::to_string(face_id));
  }
  if (listed < pieces.size())
    problems.add(std::to_string(pieces.size() - listed) + " boundary facets of the tetrahedra are missing from the file's boundary triangles");
}

// Steps 2 and 3 (the input points are checked): the boundary of the tetrahedra is the input's
// surface, refined. Returns it as a PLC, each piece with its tetrahedron on the positive side, and
// in `off_input`, per piece, whether its facet holds a point off its input segment (surface_points.h).
Plc<3> verify_surface(const Plc<3>& input, const TetMeshView& mesh, const Triangulation<3>& tets, FacetMode mode,
                      MeshVerification& v, std::vector<char>* off_input = nullptr) {
  Problems problems(v);
  // 2. The facets, and the Steiner points on them.
  const SurfaceFacets facets = detail::group_surface_facets(input, mode);
  v.facets = facets.num_facets();
  const SurfacePoints on = detail::locate_points(input, facets, mesh.points, problems);
  v.steiner_exactly_on = on.exactly_on;
  Plc<3> refined;
  if (!v.ok()) return refined;

  // 3. The boundary of the tetrahedra: pieces of the facets, tiling them.
  const std::vector<Triangle> boundary = boundary_of(tets);
  v.boundary_triangles = boundary.size();
  const std::vector<uint32_t> facet_of = detail::verify_facet_patches(input, facets, on, mesh.points, boundary, problems);
  if (!v.ok()) return refined;
  refined.points.assign(mesh.points.begin(), mesh.points.end());
  Pieces pieces;
  pieces.reserve(boundary.size());
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    Triangle key = boundary[i];
    std::sort(key.begin(), key.end());
    pieces.push_back({key, {boundary[i], facet_of[i]}});
    refined.simplices.insert(refined.simplices.end(), boundary[i].begin(), boundary[i].end());
    refined.exterior.push_back(ExteriorSide::Negative);
    refined.tags.push_back(facets.first_triangle(facet_of[i]));
    if (off_input) off_input->push_back(on.off_facet[facet_of[i]]);
  }
  if (!std::is_sorted(pieces.begin(), pieces.end())) std::sort(pieces.begin(), pieces.end());  // boundary_of lists them so
  check_file_boundary(mesh, pieces, input, facets, problems, v);
  return refined;
}

// Steps 1 to 4 under one FacetMode.
MeshVerification verify_in_mode(const Plc<3>& input, const TetMeshView& mesh, FacetMode mode) {
  MeshVerification v;
  Problems problems(v);
  const std::size_t n = input.num_points(), total = mesh.num_points();

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

  // The tetrahedra as a triangulation (the ids are checked), for steps 3 and 4. No neighbours: a
  // file has none to check, and validate() pairs the facets itself.
  Triangulation<3> tri;
  tri.points.assign(mesh.points.begin(), mesh.points.end());
  tri.num_input_points = static_cast<uint32_t>(total);
  tri.simplices.assign(mesh.tetrahedra.begin(), mesh.tetrahedra.end());
  if (mesh.regions.size() == mesh.num_tetrahedra()) tri.regions.assign(mesh.regions.begin(), mesh.regions.end());

  std::vector<char> off_input;
  Plc<3> refined = verify_surface(input, mesh, tri, mode, v, &off_input);
  if (!v.ok()) {
    // A mesh made with --facets coplanar fails as triangles here; say so when it would pass.
    if (mode == FacetMode::Triangles) {
      MeshVerification as_coplanar;
      verify_surface(input, mesh, tri, FacetMode::Coplanar, as_coplanar);
      v.suggest_coplanar = as_coplanar.ok();
    }
    return v;
  }

  // 4. validate(): against the input itself when it is the surface as given.
  const bool exact_input = v.steiner_points == 0 && mode == FacetMode::Triangles;
  if (!exact_input) {
    // Pieces of different facets must not cross. A facet whose points all lie exactly on it (its
    // input vertices, Steiner points strictly inside its segments) is tiled by its pieces (step 3,
    // exact in its plane), so they meet the others as the input's facets do: properly, when the
    // input is a valid PLC (a record of its check says so; else it is checked here). Only the pairs
    // with a piece of a facet holding a point off its segment are tested (refined_check.h, as in
    // cdt()); the rest of the PLC check runs on every piece.
    for (const auto& p : find_problems(input, Problems::kShown)) problems.add("input surface: " + p.message);
    if (!v.ok()) return v;
    try {
      detail::check_refined(refined, off_input);
    } catch (const PlcError& e) {
      for (const auto& p : e.problems()) problems.add("refined surface: " + p.message);
    }
    if (!v.ok()) return v;
  }
  const Plc<3>& plc = exact_input ? input : refined;
  ValidationReport report = validate(tri, plc);
  // Paper §6: cdt() tries further perturbation orders when the vertex-id order leaves the PLC as
  // given without a CDT (sweepcdt/perturbation_order.h), ranked on the input; so does this, when
  // only the local Delaunay test failed — the one check the order can change. Steiner points come
  // with the vertex-id order.
  for (int order = 1; v.steiner_points == 0 && order < kPerturbationOrders && report.counts.size() == 1 && report.count("locally-delaunay"); ++order) {
    tri.perturbation_rank = perturbation_rank(input, order);
    ValidationReport in_order = validate(tri, plc);
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

}  // namespace

MeshVerification verify_cdt(const Plc<3>& input, const TetMeshView& mesh, FacetMode facets) {
  MeshVerification v = verify_in_mode(input, mesh, facets);
  // The default mode is mesh's (coplanar): a mesh made with --facets triangles fails it for its face ids.
  if (!v.ok() && facets == FacetMode::Coplanar) v.suggest_triangles = verify_in_mode(input, mesh, FacetMode::Triangles).ok();
  return v;
}

}  // namespace sweepcdt
