// inspect() and to_plc() on hand-made surfaces: welding, every kind of surface problem, orientation
// repair, nesting of shells (cavities, bodies in cavities), and the exact point-in-shell test.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "nesting.h"
#include "surface_builders.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io {
namespace {

using testing::add_cube;
using testing::add_tetrahedron;
using testing::cube_soup;

SurfaceReport inspect_soup(const Soup& soup) { return inspect(weld(soup)); }

TEST(Weld, MergesExactlyEqualCoordinatesOnly) {
  Soup soup;
  soup.file = "w";
  soup.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, /* again: */ 1, 0, 0, -0.0, 0, 0, 0, 1, 1e-300};
  soup.triangles = {0, 1, 2, 3, 4, 5};
  const Surface s = weld(soup);
  EXPECT_EQ(s.points_in_file, 6u);
  EXPECT_EQ(s.num_points(), 4u) << "(1,0,0) and (1,0,0) merge, -0 equals 0, but 1e-300 is not 0";
  EXPECT_EQ(s.triangles, (std::vector<uint32_t>{0, 1, 2, 1, 0, 3}));
}

// Many points, most of them repeats (-0 and +0 among them, and one-ulp neighbours that must stay
// apart), against the definition: each point is represented by the first with equal coordinates,
// and the surface numbers representatives by first use.
TEST(Weld, EachPointBecomesTheFirstWithEqualCoordinates) {
  std::mt19937 rng(7);
  const std::vector<double> values = {0.0, -0.0, 1.0, std::nextafter(1.0, 2.0), -3.5, 1e-300, 0.1f};
  Soup soup;
  soup.file = "many";
  for (int i = 0; i < 3000; ++i)
    for (int k = 0; k < 3; ++k) soup.points.push_back(values[rng() % values.size()]);
  for (int c = 0; c < 3 * 2000; ++c) soup.triangles.push_back(static_cast<uint32_t>(rng() % 3000));
  std::vector<uint32_t> first(3000);
  for (uint32_t i = 0; i < 3000; ++i) {
    first[i] = i;
    for (uint32_t j = 0; j < i; ++j)
      if (soup.points[3 * j] == soup.points[3 * i] && soup.points[3 * j + 1] == soup.points[3 * i + 1] &&
          soup.points[3 * j + 2] == soup.points[3 * i + 2]) {
        first[i] = j;
        break;
      }
  }
  std::vector<uint32_t> id(3000, UINT32_MAX), triangles;
  std::vector<double> points;
  for (const uint32_t v : soup.triangles) {
    const uint32_t r = first[v];
    if (id[r] == UINT32_MAX) {
      id[r] = static_cast<uint32_t>(points.size() / 3);
      points.insert(points.end(), soup.points.begin() + 3 * r, soup.points.begin() + 3 * r + 3);
    }
    triangles.push_back(id[r]);
  }
  const Surface s = weld(soup);
  EXPECT_EQ(s.triangles, triangles);
  ASSERT_EQ(s.points.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_EQ(std::signbit(s.points[i]), std::signbit(points[i])) << "coordinate " << i << ": not the first point's";
  EXPECT_EQ(s.points, points);
  EXPECT_GE(s.num_points(), 200u);  // of 6^3 = 216 (-0 and +0 are one value of the pool's seven): most used
}

TEST(Weld, DropsUnusedPoints) {
  Soup soup = cube_soup();
  soup.points.insert(soup.points.end(), {5, 5, 5});
  EXPECT_EQ(weld(soup).num_points(), 8u);
}

TEST(Inspect, OutwardCubeIsValidAndNeedsNoRepair) {
  const SurfaceReport r = inspect_soup(cube_soup());
  EXPECT_TRUE(r.valid());
  EXPECT_TRUE(r.closed && r.manifold && r.oriented);
  EXPECT_EQ(r.reversed_triangles, 0u);
  EXPECT_EQ(r.box_max, (std::array<double, 3>{1, 1, 1}));
}

// The intersection test runs once on the import path: inspect() records it, to_plc() passes the
// record on, cdt() relies on it only while it covers the PLC.
TEST(Inspect, ValidSurfaceCarriesItsCheckIntoCdt) {
  const Surface s = weld(cube_soup());
  const SurfaceReport r = inspect(s);
  ASSERT_TRUE(r.checked);
  Plc<3> plc = to_plc(s, r);
  EXPECT_TRUE(plc.checked && plc.checked->covers(plc));
  CdtStatistics stats;
  Options options;
  options.statistics = &stats;
  const Triangulation<3> tri = cdt(plc, options);
  EXPECT_TRUE(stats.check_recorded);
  // Point 0 moved onto point 1: a problem only the geometric checks (which the record skips) find.
  for (int k = 0; k < 3; ++k) plc.points[k] = plc.points[3 + k];
  EXPECT_FALSE(plc.checked->covers(plc));
  EXPECT_THROW(cdt(plc, options), PlcError);
  EXPECT_FALSE(stats.check_recorded);

  Soup broken = cube_soup();
  broken.triangles.resize(broken.triangles.size() - 3);  // open: invalid, so to_plc() passes nothing on
  const Surface open = weld(broken);
  EXPECT_THROW(to_plc(open, inspect(open)), SurfaceError);
}

TEST(Inspect, InsideOutCubeIsReversed) {
  const Surface s = weld(cube_soup(0, 1, false));
  const SurfaceReport r = inspect(s);
  EXPECT_TRUE(r.valid());
  EXPECT_TRUE(r.oriented) << "consistently oriented, only the wrong way";
  EXPECT_EQ(r.reversed_triangles, 12u);
  const Plc<3> plc = to_plc(s, r);
  for (ExteriorSide e : plc.exterior) EXPECT_EQ(e, ExteriorSide::Positive);
}

TEST(Inspect, InconsistentOrientationIsRepairedTriangleByTriangle) {
  Soup soup = cube_soup();
  std::swap(soup.triangles[3 * 5 + 1], soup.triangles[3 * 5 + 2]);  // triangle 5 now faces inward
  const SurfaceReport r = inspect_soup(soup);
  EXPECT_FALSE(r.oriented);
  EXPECT_TRUE(r.valid());
  EXPECT_EQ(r.reversed_triangles, 1u);
  EXPECT_EQ(r.reverse[5], 1u);
}

TEST(Inspect, OpenSurfaceReportsBoundaryEdges) {
  Soup soup = cube_soup();
  soup.triangles.resize(soup.triangles.size() - 6);  // remove the top face (two triangles)
  const SurfaceReport r = inspect_soup(soup);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.count(SurfaceProblemKind::BoundaryEdge), 4u);
  EXPECT_FALSE(r.valid());
  EXPECT_THROW(to_plc(weld(soup), r), SurfaceError);
}

TEST(Inspect, DegenerateAndDuplicateTriangles) {
  Soup soup = cube_soup();
  soup.points.insert(soup.points.end(), {2, 2, 2, 3, 3, 3, 4, 4, 4});
  soup.triangles.insert(soup.triangles.end(), {8, 9, 10, /* repeated vertex: */ 0, 0, 1, /* duplicate of 0: */ 0, 6, 4});
  const SurfaceReport r = inspect_soup(soup);
  EXPECT_EQ(r.count(SurfaceProblemKind::DegenerateTriangle), 2u);
  EXPECT_EQ(r.count(SurfaceProblemKind::DuplicateTriangle), 1u);
  EXPECT_FALSE(r.closed);
}

TEST(Inspect, NonManifoldEdgeAndPinchedVertex) {
  // Two boxes sharing the edge x = y = 1: four triangles around it.
  Soup edge = cube_soup(0, 1);
  testing::add_box(edge, {1, 1, 0}, {2, 2, 1});
  const SurfaceReport r = inspect_soup(edge);
  EXPECT_EQ(r.count(SurfaceProblemKind::NonManifoldEdge), 1u);
  EXPECT_FALSE(r.manifold);
  EXPECT_FALSE(r.closed);

  // Two tetrahedra sharing one vertex: closed edges, but a pinch.
  Soup pinch;
  pinch.file = "pinch";
  add_tetrahedron(pinch, 0, 0, 0);
  add_tetrahedron(pinch, -1, 0, 0);  // its corner (0, 0, 0) is the first one's
  const SurfaceReport p = inspect_soup(pinch);
  EXPECT_EQ(p.count(SurfaceProblemKind::NonManifoldVertex), 1u);
  EXPECT_TRUE(p.closed);
  EXPECT_FALSE(p.manifold);
}

TEST(Inspect, MobiusStripIsNonOrientable) {
  // A strip of 5 quads whose ends are glued with a half twist.
  Soup soup;
  soup.file = "mobius";
  const int n = 5;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.141592653589793 * i / n, c = std::cos(a), s = std::sin(a), t = std::cos(a / 2), u = std::sin(a / 2);
    soup.points.insert(soup.points.end(), {c * (3 - t), s * (3 - t), -u, c * (3 + t), s * (3 + t), u});
  }
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t a = 2 * i, b = 2 * i + 1;
    uint32_t c = 2 * (i + 1), d = 2 * (i + 1) + 1;
    if (i == n - 1) c = 1, d = 0;  // the twist
    soup.triangles.insert(soup.triangles.end(), {a, b, d, a, d, c});
  }
  const SurfaceReport r = inspect_soup(soup);
  EXPECT_EQ(r.count(SurfaceProblemKind::NonOrientable), 1u);
}

TEST(Inspect, SelfIntersectingCubesAreReportedInPairs) {
  Soup soup = cube_soup(0, 2);
  add_cube(soup, 1, 3);
  const SurfaceReport r = inspect_soup(soup);
  EXPECT_GT(r.count(SurfaceProblemKind::SelfIntersection), 0u);
  EXPECT_FALSE(r.valid());
  for (const auto& p : r.problems) {
    if (p.kind != SurfaceProblemKind::SelfIntersection) continue;
    EXPECT_LT(p.elements[0], 12u);
    EXPECT_GE(p.elements[1], 12u);
  }
}

TEST(Nesting, CavityAndBodyInsideIt) {
  // Outer cube [0,9], cavity [1,8] given outward (so it must be reversed), body [3,6] inward (so it
  // must be reversed too), and a disjoint cube [20,21].
  Soup soup = cube_soup(0, 9);
  add_cube(soup, 1, 8, true);
  add_cube(soup, 3, 6, false);
  add_cube(soup, 20, 21, true);
  const Surface s = weld(soup);
  const SurfaceReport r = inspect(s);
  ASSERT_TRUE(r.valid());
  ASSERT_EQ(r.shells.size(), 4u);
  EXPECT_EQ(r.shells[0].depth, 0u);
  EXPECT_EQ(r.shells[1].depth, 1u);
  EXPECT_EQ(r.shells[1].parent, 0);
  EXPECT_EQ(r.shells[2].depth, 2u);
  EXPECT_EQ(r.shells[2].parent, 1);
  EXPECT_EQ(r.shells[3].depth, 0u);
  EXPECT_EQ(r.nested_shells(), 2u);
  EXPECT_EQ(r.reversed_triangles, 24u);
  EXPECT_TRUE(r.shells[1].reversed && r.shells[2].reversed);
  const Plc<3> plc = to_plc(s, r);
  EXPECT_NO_THROW(check(plc));
  for (std::size_t t = 0; t < 48; ++t) {
    const bool reversed = t >= 12 && t < 36;
    EXPECT_EQ(plc.exterior[t], reversed ? ExteriorSide::Positive : ExteriorSide::Negative) << "triangle " << t;
  }
}

// Twice the volume enclosed by the soup's triangles (positive for outward ones), in doubles.
double volume_of(const Soup& soup, std::size_t first_triangle, std::size_t end_triangle) {
  double v = 0;
  for (std::size_t t = first_triangle; t < end_triangle; ++t) {
    const double* a = soup.points.data() + 3 * soup.triangles[3 * t];
    const double* b = soup.points.data() + 3 * soup.triangles[3 * t + 1];
    const double* c = soup.points.data() + 3 * soup.triangles[3 * t + 2];
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return v / 6;
}

TEST(Nesting, TheDomainIsMaterialOnlyAndBodiesAreSeparateRegions) {
  // Icosahedra rather than cubes: their edges stay strongly Delaunay (no vertex of another shell in
  // an edge's diametral ball), so a CDT exists without Steiner points.
  Soup soup;
  soup.file = "nested";
  testing::add_icosahedron(soup, 5);
  testing::add_icosahedron(soup, 1);  // the cavity, given outward: to be reversed
  add_tetrahedron(soup, 0, 0, 0);  // a body inside the cavity, shrunk to edge 0.2 around the centre
  for (std::size_t i = 24 * 3; i < soup.points.size(); ++i) soup.points[i] = soup.points[i] * 0.2 - 0.05;
  const Surface s = weld(soup);
  const SurfaceReport r = inspect(s);
  ASSERT_TRUE(r.valid());
  EXPECT_EQ(r.shells[2].depth, 2u);
  const Triangulation<3> tri = cdt(to_plc(s, r));
  double volume = 0;
  std::set<int32_t> regions;
  for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
    const uint32_t* v = tri.simplex(t);
    volume += predicates::orient_value<3>({tri.point(v[0]), tri.point(v[1]), tri.point(v[2]), tri.point(v[3])}) / 6;
    regions.insert(tri.regions[t]);
  }
  const double expected = volume_of(soup, 0, 20) - volume_of(soup, 20, 40) + volume_of(soup, 40, 44);
  EXPECT_NEAR(std::abs(volume), expected, 1e-9 * expected) << "the cavity is a hole, the body inside it is meshed";
  EXPECT_EQ(regions.size(), 2u);
}

TEST(PointInShell, AgreesWithTheBoxOnEveryGridPointIncludingRayDegeneracies) {
  // Rays from grid points run along cube edges, through vertices and along face diagonals.
  const Surface cube = weld(cube_soup(0, 4));
  std::vector<uint32_t> all(cube.num_triangles());
  for (uint32_t t = 0; t < all.size(); ++t) all[t] = t;
  for (int x = -1; x <= 5; ++x)
    for (int y = -1; y <= 5; ++y)
      for (int z = -1; z <= 5; ++z) {
        const bool on_boundary = (x >= 0 && x <= 4 && y >= 0 && y <= 4 && z >= 0 && z <= 4) &&
                                 (x == 0 || x == 4 || y == 0 || y == 4 || z == 0 || z == 4);
        if (on_boundary) continue;
        const double q[3] = {double(x), double(y), double(z)};
        const bool inside = x > 0 && x < 4 && y > 0 && y < 4 && z > 0 && z < 4;
        EXPECT_EQ(detail::inside_shell(cube, all, q), inside) << x << " " << y << " " << z;
      }
}

}  // namespace
}  // namespace sweepcdt::io
