// Polygons of OFF/OBJ/PLY: planar ones triangulated exactly (fan if convex, ear clipping otherwise),
// non-planar, self-crossing or degenerate ones refused with BadPolygon.
#include <cmath>
#include <cstdio>

#include "io_test_util.h"

namespace sweepcdt::io {
namespace {

using testing::expect_input_error;

// An OFF file with one polygon through the given points (x y z each).
std::string polygon_off(const std::vector<std::array<double, 3>>& points) {
  std::string s = "OFF\n" + std::to_string(points.size()) + " 1 0\n";
  char line[100];
  for (const auto& p : points) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    s += line;
  }
  s += std::to_string(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) s += " " + std::to_string(i);
  return s + "\n";
}

// Twice the signed area of each triangle projected to the xy plane.
std::vector<double> doubled_areas_xy(const Soup& soup) {
  std::vector<double> areas;
  for (std::size_t t = 0; t < soup.num_triangles(); ++t) {
    const double* a = soup.points.data() + 3 * soup.triangles[3 * t];
    const double* b = soup.points.data() + 3 * soup.triangles[3 * t + 1];
    const double* c = soup.points.data() + 3 * soup.triangles[3 * t + 2];
    areas.push_back((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  }
  return areas;
}

double sum(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s;
}

TEST(Polygon, ConvexPolygonsAreFanned) {
  const Soup soup = read_soup_from_memory(polygon_off({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {2, 2, 0}, {0, 2, 0}}), "p.off");
  ASSERT_EQ(soup.num_triangles(), 3u);
  EXPECT_EQ(soup.triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
}

TEST(Polygon, NonConvexPolygonIsEarClippedKeepingOrientationAndArea) {
  // An L-shape, counterclockwise, doubled area 2 * 3 = 6; a fan from vertex 0 would leave the shape.
  const std::vector<std::array<double, 3>> l{{0, 0, 5}, {2, 0, 5}, {2, 1, 5}, {1, 1, 5}, {1, 2, 5}, {0, 2, 5}};
  for (std::size_t start = 0; start < l.size(); ++start) {
    std::vector<std::array<double, 3>> rotated(l.begin() + static_cast<std::ptrdiff_t>(start), l.end());
    rotated.insert(rotated.end(), l.begin(), l.begin() + static_cast<std::ptrdiff_t>(start));
    const Soup soup = read_soup_from_memory(polygon_off(rotated), "l.off");
    ASSERT_EQ(soup.num_triangles(), 4u);
    const auto areas = doubled_areas_xy(soup);
    for (double a : areas) EXPECT_GT(a, 0) << "every triangle keeps the polygon's orientation";
    EXPECT_EQ(sum(areas), 6.0) << "the triangles tile the polygon";
  }
}

TEST(Polygon, TiltedPlanarPolygonWithAVertexOnAnEdge) {
  // In the plane z = x + y (exactly representable); vertex 2 lies on edge 1-3.
  const Soup soup = read_soup_from_memory(polygon_off({{0, 0, 0}, {2, 0, 2}, {2, 1, 3}, {2, 2, 4}, {0, 2, 2}}), "t.off");
  ASSERT_EQ(soup.num_triangles(), 3u);
  const auto areas = doubled_areas_xy(soup);
  for (double a : areas) EXPECT_GT(a, 0);
  EXPECT_EQ(sum(areas), 8.0);
}

TEST(Polygon, NonPlanarPolygonIsRefused) {
  expect_input_error("q.off", polygon_off({{0, 0, 0}, {1, 0, 0}, {1, 1, 1e-300}, {0, 1, 0}}), InputErrorKind::BadPolygon, "is not planar");
}

TEST(Polygon, SelfCrossingPolygonsAreRefused) {
  // Pentagram: turns one way everywhere but winds twice.
  std::vector<std::array<double, 3>> star;
  const double pentagon[5][2] = {{0, 10}, {6, -8}, {-10, 3}, {10, 3}, {-6, -8}};
  for (const auto& p : pentagon) star.push_back({p[0], p[1], 0});
  expect_input_error("s.off", polygon_off(star), InputErrorKind::BadPolygon, "is not simple");
  // Bow tie.
  expect_input_error("b.off", polygon_off({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}), InputErrorKind::BadPolygon, "is not simple");
}

TEST(Polygon, DegeneratePolygonsAreRefused) {
  expect_input_error("c.off", polygon_off({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}), InputErrorKind::BadPolygon, "collinear");
  expect_input_error("r.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 1\n", InputErrorKind::BadPolygon, "names vertex 1 twice");
}

TEST(Polygon, ObjAndPlyPolygonsUseTheSameTriangulation) {
  const Soup obj = read_soup_from_memory("v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 1 2 3 4 5 6\n", "l.obj");
  EXPECT_EQ(obj.num_triangles(), 4u);
  EXPECT_EQ(sum(doubled_areas_xy(obj)), 6.0);
  const Soup ply = read_soup_from_memory(
      "ply\nformat ascii 1.0\nelement vertex 6\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n6 0 1 2 3 4 5\n",
      "l.ply");
  EXPECT_EQ(ply.triangles, obj.triangles);
}

}  // namespace
}  // namespace sweepcdt::io
