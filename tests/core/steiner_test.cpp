// SteinerMode::Auto (issue 7): PLCs without a CDT get one after splitting segments that are not
// strongly Delaunay; the result is exactly the CDT of the refined PLC, and every Steiner point lies
// on its recorded input triangle to within rounding.
#include <gtest/gtest.h>

#include <cmath>

#include "sweepcdt/cdt.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/validate.h"
#include "test_shapes.h"

using namespace sweepcdt;

namespace {

// Distance from p to the plane of triangle t, relative to the largest coordinate involved: the
// exact determinant (rounded once) over twice the area.
double relative_plane_distance(const Plc<3>& plc, const uint32_t* t, const double* p) {
  const double* a = plc.point(t[0]);
  const double* b = plc.point(t[1]);
  const double* c = plc.point(t[2]);
  const double det = predicates::orient_value<3>({a, b, c, p});
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n = std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
  double scale = 0;
  for (const double* q : {a, b, c, p})
    for (int k = 0; k < 3; ++k) scale = std::max(scale, std::fabs(q[k]));
  return std::fabs(det) / n / scale;
}

void expect_steiner_cdt(const Plc<3>& plc, const std::string& what, bool expect_points) {
  Options options;
  options.steiner = SteinerMode::Auto;
  CdtStatistics stats;
  options.statistics = &stats;
  Plc<3> refined;
  Triangulation<3> tri;
  try {
    tri = cdt(plc, options, &refined);
  } catch (const std::exception& e) {
    FAIL() << what << ": " << e.what();
  }
  const auto report = validate_triangulated(tri, refined);
  EXPECT_TRUE(report.ok()) << what << "\n" << report.summary();
  EXPECT_EQ(tri.num_input_points, plc.num_points());
  EXPECT_EQ(tri.steiner_on.size(), tri.num_points() - plc.num_points());
  EXPECT_EQ(stats.steiner_points, tri.steiner_on.size());
  if (expect_points) EXPECT_GT(tri.steiner_on.size(), 0u) << what;
  for (std::size_t k = 0; k < tri.steiner_on.size(); ++k) {
    const double* p = tri.point(static_cast<uint32_t>(tri.num_input_points + k));
    ASSERT_LT(tri.steiner_on[k], plc.num_simplices());
    // Within a few units of roundoff of the input triangle's plane.
    EXPECT_LT(relative_plane_distance(plc, plc.simplex(tri.steiner_on[k]), p), 1e-15) << what << " Steiner point " << k;
  }
  // Every refined triangle carries its input triangle as its tag.
  ASSERT_EQ(refined.tags.size(), refined.num_simplices());
  for (uint32_t tag : refined.tags) EXPECT_LT(tag, plc.num_simplices());
}

TEST(Steiner, SchonhardtPrismsGetACdt) {
  for (double twist : {0.0, 0.2, 0.5, 1e-9}) {
    const Plc<3> prism = fixtures::twisted_prism(twist);
    EXPECT_THROW(cdt(prism), NoCdtError);  // SteinerMode::None keeps the input exactly
    expect_steiner_cdt(prism, "twist " + std::to_string(twist), true);
  }
}

TEST(Steiner, CosphericalCubeWithoutCdtUnderItsVertexOrder) {
  expect_steiner_cdt(fixtures::grid_box_surface(1), "grid box 1", true);
  expect_steiner_cdt(fixtures::grid_box_surface(3), "grid box 3", true);
}

TEST(Steiner, NothingToDoWhenACdtExists) {
  Options options;
  options.steiner = SteinerMode::Auto;
  const Plc<3> cube = fixtures::unit_cube_surface();
  const auto plain = cdt(cube);
  const auto steiner = cdt(cube, options);
  EXPECT_EQ(steiner.num_points(), plain.num_points());
  EXPECT_EQ(steiner.simplices.size(), plain.simplices.size());
}

}  // namespace
