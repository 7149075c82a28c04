// The io functions the MeshLab filter calls (issue 15): problem_triangles (what to select on bad
// input), cut_away (the layer that shows the tetrahedra) and radius_ratio (its colours). Expectations
// come from the test's own constructions, not from the functions under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "surface_builders.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/cut_away.h"
#include "sweepcdt/io/problem_triangles.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/io/tetrahedron_quality.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::io {
namespace {

std::vector<uint32_t> selected(const Soup& soup) {
  const Surface s = weld(soup);
  return problem_triangles(s, inspect(s, SIZE_MAX));
}

TEST(ProblemTriangles, ValidCubeSelectsNothing) { EXPECT_TRUE(selected(testing::cube_soup()).empty()); }

TEST(ProblemTriangles, OpenCubeSelectsTheTrianglesAtTheHole) {
  Soup soup = testing::cube_soup();
  const std::array<uint32_t, 3> removed{soup.triangles[33], soup.triangles[34], soup.triangles[35]};
  soup.triangles.resize(33);  // triangle 11 gone: its three edges have one triangle each
  std::vector<uint32_t> expected;
  for (uint32_t t = 0; t < 11; ++t) {
    int shared = 0;
    for (int i = 0; i < 3; ++i) shared += std::count(removed.begin(), removed.end(), soup.triangles[3 * t + i]);
    if (shared == 2) expected.push_back(t);
  }
  ASSERT_EQ(expected.size(), 3u);  // its partner in the quad and two neighbours on other faces
  EXPECT_EQ(selected(soup), expected);
}

TEST(ProblemTriangles, PinchedVertexSelectsEveryTriangleAtIt) {
  Soup soup;
  soup.file = "pinch";
  testing::add_tetrahedron(soup, 0, 0, 0);    // corner (0, 0, 0) ...
  testing::add_tetrahedron(soup, -1, -1, -1); // ... and (0, -1, -1), (-1, 0, -1), (-1, -1, 0): disjoint
  // Move the second one so that its corner (0, -1, -1) becomes the first one's (0, 0, 0).
  for (std::size_t p = 4; p < 8; ++p) {
    soup.points[3 * p + 1] += 1;
    soup.points[3 * p + 2] += 1;
  }
  std::vector<uint32_t> expected;  // the triangles naming the point (0, 0, 0)
  for (uint32_t t = 0; t < soup.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const double* q = soup.points.data() + 3 * soup.triangles[3 * t + i];
      if (q[0] == 0 && q[1] == 0 && q[2] == 0) expected.push_back(t);
    }
  ASSERT_EQ(expected.size(), 6u);
  EXPECT_EQ(selected(soup), expected);
}

TEST(ProblemTriangles, OverlappingCubesSelectOnlyTrianglesThatCross) {
  Soup soup;
  soup.file = "two cubes";
  testing::add_cube(soup, 0, 2);
  testing::add_box(soup, {1, 1, 1}, {3, 3, 3});
  const std::vector<uint32_t> s = selected(soup);
  ASSERT_FALSE(s.empty());
  // The faces x = 0, y = 0, z = 0 of the first cube and x = 3, y = 3, z = 3 of the second are far
  // from the other cube: none of their triangles may be selected.
  for (uint32_t t : s) {
    bool far = false;
    for (int axis = 0; axis < 3; ++axis) {
      bool all = true;
      const double side = t < 12 ? 0 : 3;
      for (int i = 0; i < 3; ++i) all = all && soup.points[3 * soup.triangles[3 * t + i] + axis] == side;
      far = far || all;
    }
    EXPECT_FALSE(far) << "triangle " << t;
  }
  // Every face of each cube that enters the other (x = 2, y = 2, z = 2 of the first) has both of its
  // triangles crossing the second cube's faces or lying inside it: at least one of them is selected.
  for (int axis = 0; axis < 3; ++axis) {
    bool found = false;
    for (uint32_t t : s)
      if (t < 12) {
        bool all = true;
        for (int i = 0; i < 3; ++i) all = all && soup.points[3 * soup.triangles[3 * t + i] + axis] == 2;
        found = found || all;
      }
    EXPECT_TRUE(found) << "axis " << axis;
  }
}

TEST(ProblemTriangles, TrianglesAtVertices) {
  const Surface s = weld(testing::cube_soup());
  // Every vertex of a triangulated cube's corner has 3 to 6 triangles; count them directly.
  for (uint32_t v = 0; v < s.num_points(); ++v) {
    std::vector<uint32_t> expected;
    for (uint32_t t = 0; t < s.num_triangles(); ++t)
      if (s.triangles[3 * t] == v || s.triangles[3 * t + 1] == v || s.triangles[3 * t + 2] == v) expected.push_back(t);
    EXPECT_EQ(triangles_at_vertices(s, {v, 1000}), expected);
  }
  EXPECT_EQ(triangles_at_vertices(s, {}).size(), 0u);
  EXPECT_EQ(triangles_at_vertices(s, {0, 1, 2, 3, 4, 5, 6, 7}).size(), 12u);
}

VolumeMesh mesh_of(const Soup& soup) {
  const Surface s = weld(soup);
  const Plc<3> plc = to_plc(s, inspect(s));
  Options options;
  options.steiner = SteinerMode::Auto;
  Plc<3> triangulated;
  const Triangulation<3> tri = cdt(plc, options, &triangulated);
  return volume_mesh_of(tri, triangulated);
}

// A triangle as (smallest id first, then the other two in cyclic order): equal for equal orientation.
std::array<uint32_t, 3> oriented(const uint32_t* t) {
  const int k = static_cast<int>(std::min_element(t, t + 3) - t);
  return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}

// Every edge used as often in one direction as in the other: the boundary of a set of
// tetrahedra, consistently oriented (kept tetrahedra that share only an edge make it non-manifold
// there: used twice each way).
void expect_closed_oriented(const std::vector<uint32_t>& triangles) {
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (std::size_t t = 0; t < triangles.size() / 3; ++t)
    for (int i = 0; i < 3; ++i) ++uses[{triangles[3 * t + i], triangles[3 * t + (i + 1) % 3]}];
  for (const auto& [edge, n] : uses) {
    const auto back = uses.find({edge.second, edge.first});
    EXPECT_TRUE(back != uses.end() && back->second == n) << edge.first << "-" << edge.second;
  }
}

Soup cube_with_cavity() {
  Soup soup;
  soup.file = "cavity";
  testing::add_cube(soup, 0, 3);
  testing::add_cube(soup, 1, 2);  // outward as given: to_plc orients it as a cavity
  return soup;
}

TEST(CutAway, WholeMeshIsTheDomainBoundaryWithItsOrientation) {
  const VolumeMesh mesh = mesh_of(cube_with_cavity());
  const CutAway cut = cut_away(mesh, 0, 1.0);
  EXPECT_EQ(cut.kept_tetrahedra, mesh.num_tetrahedra());
  std::set<std::array<uint32_t, 3>> got, want;
  for (std::size_t t = 0; t < cut.num_triangles(); ++t) got.insert(oriented(&cut.triangles[3 * t]));
  for (std::size_t t = 0; t < mesh.num_boundary(); ++t) want.insert(oriented(&mesh.boundary[3 * t]));
  EXPECT_EQ(got, want);
  EXPECT_EQ(cut.num_triangles(), mesh.num_boundary());
  EXPECT_TRUE(std::all_of(cut.on_cut.begin(), cut.on_cut.end(), [](uint8_t c) { return c == 0; }));
}

TEST(CutAway, HalfMeshIsClosedAndShowsTheCut) {
  const VolumeMesh mesh = mesh_of(cube_with_cavity());
  for (int axis = 0; axis < 3; ++axis) {
    const CutAway cut = cut_away(mesh, axis, 0.5);
    EXPECT_DOUBLE_EQ(cut.position, 1.5);
    EXPECT_GT(cut.kept_tetrahedra, 0u);
    EXPECT_LT(cut.kept_tetrahedra, mesh.num_tetrahedra());
    expect_closed_oriented(cut.triangles);
    ASSERT_EQ(cut.tetrahedron.size(), cut.num_triangles());
    ASSERT_EQ(cut.on_cut.size(), cut.num_triangles());
    std::size_t cut_faces = 0;
    for (std::size_t t = 0; t < cut.num_triangles(); ++t) {
      const uint32_t* tet = &mesh.tetrahedra[4 * cut.tetrahedron[t]];
      for (int i = 0; i < 3; ++i) EXPECT_NE(std::find(tet, tet + 4, cut.triangles[3 * t + i]), tet + 4);
      cut_faces += cut.on_cut[t];
    }
    EXPECT_GT(cut_faces, 0u);
  }
  EXPECT_EQ(cut_away(mesh, 2, 0.0).num_triangles(), 0u);  // no centroid lies on the bottom face
  EXPECT_THROW(cut_away(mesh, 3, 0.5), std::invalid_argument);
  EXPECT_THROW(cut_away(mesh, 0, 1.5), std::invalid_argument);
}

TEST(RadiusRatio, KnownTetrahedra) {
  VolumeMesh m;
  m.points = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1,  // regular (alternate cube corners)
              0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1,        // corner of a cube
              0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};       // flat
  m.tetrahedra = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  EXPECT_NEAR(radius_ratio(m, 0), 1.0, 1e-12);
  // r = 1 / (3 + sqrt 3), R = sqrt 3 / 2.
  EXPECT_NEAR(radius_ratio(m, 1), 3 * (1 / (3 + std::sqrt(3.0))) / (std::sqrt(3.0) / 2), 1e-12);
  EXPECT_EQ(radius_ratio(m, 2), 0.0);
}

}  // namespace
}  // namespace sweepcdt::io
