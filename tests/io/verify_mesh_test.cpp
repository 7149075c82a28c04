// The library's verification (io::verify_mesh, core's verify_cdt), called directly: it accepts the
// volume mesh cdt() makes of a surface and rejects meshes that are not its CDT — a tetrahedron
// removed, a vertex moved, a Steiner point moved off its edge, a 2-3 flip that keeps a valid
// tetrahedralization, tetrahedra outside the surface, boundary triangles turned, mistagged or
// missing — naming what is wrong; under FacetMode::Coplanar against the polygons of coplanar input
// triangles. The same cases as tests/cli/check_cli_test.cpp, without the command line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "io_test_util.h"
#include "surface_builders.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/verify_mesh.h"
#include "sweepcdt/io/write_surface.h"
#include "sweepcdt/steiner_point.h"
#include "sweepcdt/verify_cdt.h"
#include "tamper_mesh.h"
#include "test_shapes.h"

namespace sweepcdt::io::testing {
namespace {

// The surface as import_plc reads it back from an OFF file (welded, exterior notations).
Plc<3> imported(const TempDir& dir, const Soup& soup) {
  const auto file = dir.path() / "surface.off";
  write_surface(file, soup, Format::Off);
  return import_plc(file);
}
Plc<3> imported(const TempDir& dir, const Plc<3>& plc) {
  const auto file = dir.path() / "surface.off";
  write_surface(file, plc, Format::Off);
  return import_plc(file);
}

// What `sweepcdt mesh` writes, in memory.
VolumeMesh mesh_of(const Plc<3>& plc, SteinerMode steiner, FacetMode facets) {
  Options options;
  options.steiner = steiner;
  options.facets = facets;
  Plc<3> triangulated;
  const Triangulation<3> tri = cdt(plc, options, &triangulated);
  return volume_mesh_of(tri, triangulated);
}

// A box with a box-shaped cavity (given outward: the importer reverses it) and a body inside it.
Soup nested_boxes() {
  Soup soup;
  add_box(soup, {0, 0, 0}, {12, 11, 10});
  add_box(soup, {2, 3, 2}, {9, 8, 7});
  add_box(soup, {4, 5, 3}, {6, 6, 5});
  return soup;
}

// An icosahedron with its points moved a little (deterministically): no four cospherical, so its
// CDT is unique under every perturbation order, and a flip breaks it.
Soup jittered_icosahedron() {
  Soup soup;
  add_icosahedron(soup, 10);
  for (std::size_t i = 0; i < soup.points.size(); ++i) soup.points[i] += 0.3 * std::sin(1.7 * static_cast<double>(i) + 0.5);
  return soup;
}

bool says(const MeshVerification& v, const std::string& text) {
  return std::any_of(v.problems.begin(), v.problems.end(), [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

std::string all(const MeshVerification& v) {
  std::string s;
  for (const auto& p : v.problems) s += p + "\n";
  return s;
}

TEST(VerifyMesh, AcceptsTheCdtAndRejectsTamperedMeshes) {
  TempDir dir;
  const Plc<3> input = imported(dir, jittered_icosahedron());
  const VolumeMesh mesh = mesh_of(input, SteinerMode::None, FacetMode::Triangles);
  const MeshVerification ok = verify_mesh(input, mesh, FacetMode::Triangles);
  EXPECT_TRUE(ok.ok()) << all(ok);
  EXPECT_TRUE(ok.validated);
  EXPECT_EQ(ok.steiner_points, 0u);
  EXPECT_EQ(ok.facets, 20u);
  EXPECT_EQ(ok.boundary_triangles, 20u);
  EXPECT_TRUE(ok.file_boundary);
  EXPECT_TRUE(ok.file_tags);
  EXPECT_EQ(ok.perturbation_order, 0);

  {
    VolumeMesh m = mesh;
    m.tetrahedra.resize(m.tetrahedra.size() - 4);
    if (!m.regions.empty()) m.regions.pop_back();
    EXPECT_FALSE(verify_mesh(input, m, FacetMode::Triangles).ok());
  }
  {
    VolumeMesh m = mesh;
    m.points[3 * 7 + 1] += 1e-3;
    const MeshVerification v = verify_mesh(input, m, FacetMode::Triangles);
    EXPECT_TRUE(v.input_points_moved);
    EXPECT_TRUE(says(v, "vertex 7 is (")) << all(v);
    EXPECT_FALSE(v.validated);
  }
  {
    VolumeMesh m = mesh;
    ASSERT_TRUE(flip_one_pair(m));
    const MeshVerification v = verify_mesh(input, m, FacetMode::Triangles);
    EXPECT_TRUE(v.validated);
    EXPECT_TRUE(says(v, "locally-delaunay")) << all(v);
  }
  {
    VolumeMesh m = mesh;
    m.tetrahedra[5] = static_cast<uint32_t>(m.num_points());
    const MeshVerification v = verify_mesh(input, m, FacetMode::Triangles);
    EXPECT_TRUE(says(v, "tetrahedron 1 names vertex " + std::to_string(m.num_points()) + ", which does not exist")) << all(v);
  }
  // The mesh's own boundary triangles: orientation, tags, completeness.
  {
    VolumeMesh m = mesh;
    std::swap(m.boundary[3 * 5 + 1], m.boundary[3 * 5 + 2]);
    m.boundary_tags[9] = m.boundary_tags[9] == 0 ? 1 : 0;
    m.boundary.resize(m.boundary.size() - 3);
    m.boundary_tags.pop_back();
    const MeshVerification v = verify_mesh(input, m, FacetMode::Triangles);
    EXPECT_EQ(v.total_problems, 3u) << all(v);
    EXPECT_TRUE(says(v, "the file's boundary triangle 5 (")) << all(v);
    EXPECT_TRUE(says(v, "is oriented inward")) << all(v);
    EXPECT_TRUE(says(v, "the file's boundary triangle 9 (")) << all(v);
    EXPECT_TRUE(says(v, "but lies on input triangle")) << all(v);
    EXPECT_TRUE(says(v, "1 boundary facets of the tetrahedra are missing from the file's boundary triangles")) << all(v);
  }
  // Without boundary triangles only the tetrahedra are checked.
  {
    VolumeMesh m = mesh;
    m.boundary.clear();
    m.boundary_tags.clear();
    const MeshVerification v = verify_mesh(input, m, FacetMode::Triangles);
    EXPECT_TRUE(v.ok()) << all(v);
    EXPECT_FALSE(v.file_boundary);
  }
  // Another surface's mesh.
  EXPECT_FALSE(verify_mesh(imported(dir, cube_soup(-10, 10)), mesh, FacetMode::Triangles).ok());
}

// Each Steiner point must be exactly a point cdt() can make on an input edge.
TEST(VerifyMesh, SteinerPointsMustBeTheSplitPointsCdtMakes) {
  TempDir dir;
  const Plc<3> input = imported(dir, fixtures::twisted_prism(0.5));
  const VolumeMesh mesh = mesh_of(input, SteinerMode::Auto, FacetMode::Coplanar);
  ASSERT_GT(mesh.num_points(), 6u);
  const MeshVerification ok = verify_mesh(input, mesh, FacetMode::Coplanar);
  EXPECT_TRUE(ok.ok()) << all(ok);
  EXPECT_EQ(ok.steiner_points, mesh.num_points() - 6);

  VolumeMesh m = mesh;
  m.points[3 * 6] += 1e-9, m.points[3 * 6 + 1] -= 2e-9, m.points[3 * 6 + 2] += 3e-9;
  const MeshVerification v = verify_mesh(input, m, FacetMode::Coplanar);
  EXPECT_FALSE(v.validated);
  EXPECT_TRUE(says(v, "Steiner point 6 (")) << all(v);
  EXPECT_TRUE(says(v, "is not a rounded point of the segment of a facet's boundary edge, nor between two points of one facet")) << all(v);
}

// Tetrahedra of the nested boxes' cavity over the same points: each boundary triangle a piece of an
// input triangle, but with its tetrahedron outside.
TEST(VerifyMesh, TetrahedraOutsideTheSurfaceAreRejected) {
  TempDir dir;
  const Plc<3> input = imported(dir, nested_boxes());
  Soup cavity;
  add_box(cavity, {2, 3, 2}, {9, 8, 7});
  add_box(cavity, {4, 5, 3}, {6, 6, 5});
  const VolumeMesh outside = mesh_of(imported(dir, cavity), SteinerMode::None, FacetMode::Triangles);
  VolumeMesh m = mesh_of(input, SteinerMode::None, FacetMode::Triangles);
  m.tetrahedra.clear();
  for (uint32_t v : outside.tetrahedra) {
    uint32_t id = 0;
    while (id < m.num_points() && !std::equal(&outside.points[3 * v], &outside.points[3 * v] + 3, &m.points[3 * id])) ++id;
    ASSERT_LT(id, m.num_points());
    m.tetrahedra.push_back(id);
  }
  m.regions.assign(m.num_tetrahedra(), 1);
  m.boundary.clear();
  m.boundary_tags.clear();
  for (FacetMode mode : {FacetMode::Triangles, FacetMode::Coplanar}) {
    const MeshVerification v = verify_mesh(input, m, mode);
    EXPECT_TRUE(says(v, "has its tetrahedron on the outside of the surface")) << all(v);
    EXPECT_FALSE(v.suggest_coplanar);
    EXPECT_FALSE(v.suggest_triangles);
  }
}

// Paper §6: the grid box has its CDT under perturbation order 2 only; verify finds that order, and
// so it does against the coplanar polygons (without the face ids, which name triangles).
TEST(VerifyMesh, FindsTheLaterPerturbationOrder) {
  TempDir dir;
  const Plc<3> input = imported(dir, fixtures::grid_box_surface(2));
  VolumeMesh mesh = mesh_of(input, SteinerMode::None, FacetMode::Triangles);
  const MeshVerification v = verify_mesh(input, mesh, FacetMode::Triangles);
  EXPECT_TRUE(v.ok()) << all(v);
  EXPECT_EQ(v.perturbation_order, 2);
  mesh.boundary_tags.assign(mesh.num_boundary(), kNone);
  const MeshVerification coplanar = verify_mesh(input, mesh, FacetMode::Coplanar);
  EXPECT_TRUE(coplanar.ok()) << all(coplanar);
  EXPECT_EQ(coplanar.facets, 6u);
  EXPECT_EQ(coplanar.perturbation_order, 2);
}

// FacetMode::Coplanar: the boundary triangles tile the polygons of coplanar input triangles. Checked
// in the other mode each mesh fails, and the report says which mode it passes in.
TEST(VerifyMesh, CoplanarFacetsAndTheOtherModesSuggestion) {
  TempDir dir;
  const Plc<3> input = imported(dir, nested_boxes());
  const VolumeMesh coplanar = mesh_of(input, SteinerMode::Auto, FacetMode::Coplanar);
  const MeshVerification ok = verify_mesh(input, coplanar, FacetMode::Coplanar);
  EXPECT_TRUE(ok.ok()) << all(ok);
  EXPECT_EQ(ok.facets, 18u) << "three boxes of six faces";
  const MeshVerification as_triangles = verify_mesh(input, coplanar, FacetMode::Triangles);
  EXPECT_FALSE(as_triangles.ok());
  EXPECT_TRUE(as_triangles.suggest_coplanar);
  EXPECT_FALSE(as_triangles.suggest_triangles);

  // Made as triangles, with Steiner points on edges inside the faces: its face ids name input
  // triangles, so it fails as coplanar for them alone, and passes without them.
  const Plc<3> grid = imported(dir, fixtures::grid_box_surface(2));
  VolumeMesh triangles = mesh_of(grid, SteinerMode::Auto, FacetMode::Triangles);
  ASSERT_TRUE(verify_mesh(grid, triangles, FacetMode::Triangles).ok());
  const MeshVerification v = verify_mesh(grid, triangles, FacetMode::Coplanar);
  EXPECT_FALSE(v.ok());
  EXPECT_TRUE(v.suggest_triangles);
  EXPECT_FALSE(v.suggest_coplanar);
  EXPECT_TRUE(says(v, "but lies on the coplanar facet of input triangles")) << all(v);
  triangles.boundary_tags.assign(triangles.num_boundary(), kNone);
  const MeshVerification untagged = verify_mesh(grid, triangles, FacetMode::Coplanar);
  EXPECT_TRUE(untagged.ok()) << all(untagged);
  EXPECT_FALSE(untagged.file_tags);
}

// verify_cdt trusts the input's facets not to cross (the pieces of a facet exactly on it are tested
// only against pieces that may not be: verify_cdt.cpp) only after checking it: two tetrahedra that
// pass through each other, given as the PLC and as the mesh (each its own tetrahedron, every
// boundary triangle an input facet), are rejected for the input's crossing.
TEST(VerifyMesh, AnInputWhoseFacetsCrossIsRejected) {
  Plc<3> input;
  input.points = {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 1, 1, 1, 5, 1, 1, 1, 5, 1, 1, 1, 5};
  fixtures::add_tetrahedron(input, {0, 1, 2, 3});
  fixtures::add_tetrahedron(input, {4, 5, 6, 7});
  const std::vector<uint32_t> tetrahedra = {0, 1, 2, 3, 4, 5, 6, 7};
  for (FacetMode mode : {FacetMode::Coplanar, FacetMode::Triangles}) {
    const MeshVerification v = verify_cdt(input, TetMeshView{input.points, tetrahedra, {}, {}, {}}, mode);
    EXPECT_FALSE(v.ok());
    // With every triangle a facet and no Steiner point the input itself is validated against (and
    // validate() refuses the overlap); the input's own check stops the other mode before it.
    if (mode == FacetMode::Coplanar) EXPECT_TRUE(says(v, "input surface: simplices")) << all(v);
  }
}

// A Steiner point that no tetrahedron uses, on a facet's boundary edge or on an edge inside a facet
// (the cube's face diagonals): the facet is not tiled.
TEST(VerifyMesh, PointsNoTetrahedronUsesAreRejected) {
  TempDir dir;
  const Plc<3> input = imported(dir, cube_soup(0, 1));
  const VolumeMesh mesh = mesh_of(input, SteinerMode::None, FacetMode::Coplanar);
  ASSERT_TRUE(verify_mesh(input, mesh, FacetMode::Coplanar).ok());
  // Cube corners differing from corner 0 in one coordinate span an edge (a ridge), in two a face's
  // diagonal (inside the face's facet, an input edge or not).
  const auto differing = [&](uint32_t v) { return (mesh.points[3 * v] != mesh.points[0]) + (mesh.points[3 * v + 1] != mesh.points[1]) + (mesh.points[3 * v + 2] != mesh.points[2]); };
  for (const bool ridge : {true, false}) {
    uint32_t b = 1;
    while (b < 8 && differing(b) != (ridge ? 1 : 2)) ++b;
    ASSERT_LT(b, 8u);
    VolumeMesh m = mesh;
    double x[3];
    point_on_segment(&m.points[0], &m.points[3 * b], 0.5, x);
    m.points.insert(m.points.end(), x, x + 3);
    const MeshVerification v = verify_mesh(input, m, FacetMode::Coplanar);
    EXPECT_TRUE(says(v, ridge ? "Steiner point 8 lies on " : "Steiner point 8 lies on the coplanar facet of input triangles")) << all(v);
    EXPECT_TRUE(says(v, " but is a vertex of none of its boundary triangles")) << all(v);
    EXPECT_EQ(says(v, "is an edge of none of its boundary triangles"), ridge) << all(v);
  }
}

// The two files, read as `sweepcdt check` reads them.
TEST(VerifyMesh, Files) {
  TempDir dir;
  const auto surface = dir.path() / "boxes.off";
  write_surface(surface, nested_boxes(), Format::Off);
  const VolumeMesh mesh = mesh_of(import_plc(surface), SteinerMode::Auto, FacetMode::Coplanar);
  const auto file = dir.path() / "boxes.vtu";
  write_volume_mesh(file, mesh, MeshFormat::Vtu);
  EXPECT_TRUE(verify_mesh_files(surface, file, FacetMode::Coplanar).ok());
  EXPECT_FALSE(verify_mesh_files(surface, file, FacetMode::Triangles).ok());
  EXPECT_THROW(verify_mesh_files(surface, dir.write("junk.mesh", "not a mesh\n"), FacetMode::Coplanar), InputError);
}

}  // namespace
}  // namespace sweepcdt::io::testing
