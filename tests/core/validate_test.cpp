// validate() on small hand-made triangulations, valid and broken in one way each.
#include <gtest/gtest.h>

#include "brute_force_delaunay.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/validate.h"
#include "test_shapes.h"

using namespace sweepcdt;

namespace {

template <int D>
Triangulation<D> make(std::vector<double> points, std::vector<uint32_t> simplices) {
  Triangulation<D> tri;
  tri.points = std::move(points);
  tri.num_input_points = static_cast<uint32_t>(tri.points.size() / D);
  tri.simplices = std::move(simplices);
  compute_neighbors(tri);
  return tri;
}

template <int D>
Plc<D> points_only(const Triangulation<D>& tri) {
  Plc<D> plc;
  plc.points.assign(tri.points.begin(), tri.points.begin() + D * tri.num_input_points);
  return plc;
}

// Square (0,0),(2,0),(2,2),(0,2) with its centre: four triangles, Delaunay without ties.
Triangulation<2> square_with_centre() {
  return make<2>({0, 0, 2, 0, 2, 2, 0, 2, 1, 1}, {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4});
}

TEST(Validate, SquareWithCentreIsValid) {
  const auto tri = square_with_centre();
  const auto report = validate(tri, points_only(tri));
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(Validate, InvertedTriangleIsReported) {
  auto tri = square_with_centre();
  std::swap(tri.simplices[0], tri.simplices[1]);
  compute_neighbors(tri);
  const auto report = validate(tri, points_only(tri));
  EXPECT_GE(report.count("orientation"), 1u) << report.summary();
}

TEST(Validate, MissingTriangleBreaksTheHull) {
  auto tri = square_with_centre();
  tri.simplices.resize(9);
  compute_neighbors(tri);
  const auto report = validate(tri, points_only(tri));
  EXPECT_GE(report.count("domain-boundary"), 1u) << report.summary();
}

TEST(Validate, DuplicatedTriangleIsReported) {
  auto tri = square_with_centre();
  tri.simplices.insert(tri.simplices.end(), {0, 1, 4});
  compute_neighbors(tri);
  const auto report = validate(tri, points_only(tri));
  EXPECT_GE(report.count("facet-multiplicity"), 1u) << report.summary();
}

TEST(Validate, CorruptNeighbourIsReported) {
  auto tri = square_with_centre();
  std::swap(tri.neighbors[0], tri.neighbors[1]);
  const auto report = validate(tri, points_only(tri));
  EXPECT_GE(report.count("neighbors"), 1u) << report.summary();
}

// Two triangles apart: every point is a vertex and the boundary is closed and convex at every
// ridge, yet it is not the hull's. Only testing points against boundary facets finds that (the
// boundary's own vertices suffice: the domain lies in their convex hull). Tetrahedra in 3D and
// 4-simplices in 4D the same way.
TEST(Validate, SeparateConvexPiecesAreNotTheHull) {
  const auto two = make<2>({0, 0, 1, 0, 0, 1, 3, 0, 4, 0, 3, 1}, {0, 1, 2, 3, 4, 5});
  EXPECT_GE(validate(two, points_only(two)).count("domain-boundary"), 1u) << validate(two, points_only(two)).summary();
  const auto one = make<2>({0, 0, 1, 0, 0, 1}, {0, 1, 2});
  EXPECT_TRUE(validate(one, points_only(one)).ok()) << validate(one, points_only(one)).summary();

  const auto two3 = make<3>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 3, 0, 0, 4, 0, 0, 3, 1, 0, 3, 0, 1}, {1, 0, 2, 3, 5, 4, 6, 7});
  EXPECT_GE(validate(two3, points_only(two3)).count("domain-boundary"), 1u) << validate(two3, points_only(two3)).summary();
  EXPECT_EQ(validate(two3, points_only(two3)).count("orientation"), 0u);

  std::vector<double> p4;
  for (const double shift : {0.0, 3.0})
    for (int i = 0; i < 5; ++i)
      for (int k = 0; k < 4; ++k) p4.push_back((k == 0 ? shift : 0.0) + (i == k + 1 ? 1.0 : 0.0));
  const auto two4 = make<4>(p4, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  EXPECT_GE(validate(two4, points_only(two4)).count("domain-boundary"), 1u) << validate(two4, points_only(two4)).summary();
  EXPECT_EQ(validate(two4, points_only(two4)).count("orientation"), 0u);
}

TEST(Validate, UnusedPointOfTheHullIsReported) {
  auto tri = square_with_centre();
  tri.simplices = {0, 1, 2, 0, 2, 3};  // centre left out
  compute_neighbors(tri);
  const auto report = validate(tri, points_only(tri));
  EXPECT_GE(report.count("unused-vertex"), 1u) << report.summary();
}

// Kite a=(0,0), b=(2,-1), c=(4,0), d=(2,1): d lies inside the circle of abc, so diagonal bd is
// Delaunay and ac is not — unless ac is a constraint.
TEST(Validate, NonDelaunayDiagonalFailsUnlessConstrained) {
  const std::vector<double> kite = {0, 0, 2, -1, 4, 0, 2, 1};
  const auto good = make<2>(kite, {0, 1, 3, 1, 2, 3});
  const auto bad = make<2>(kite, {0, 1, 2, 0, 2, 3});
  Plc<2> plc = points_only(good);
  EXPECT_TRUE(validate(good, plc).ok()) << validate(good, plc).summary();
  const auto report = validate(bad, plc);
  EXPECT_EQ(report.count("locally-delaunay"), 1u) << report.summary();
  EXPECT_TRUE(validate(bad, plc, ValidationLevel::Topology).ok());

  plc.simplices = {0, 2};
  EXPECT_TRUE(validate(bad, plc).ok()) << validate(bad, plc).summary();
  EXPECT_EQ(validate(good, plc).count("constraints"), 1u);
}

// Two positively oriented simplices on the same side of their shared facet (they overlap): reported
// as interior-facet-sides, in 2D and 3D, and in every vertex order of the second simplex that keeps
// it positive (the side is decided from the permutation between the two vertex orders when
// orientation() found the simplices positive, validate.cpp).
TEST(Validate, SimplicesOnTheSameSideOfTheirFacet) {
  const std::vector<double> square = {0, 0, 1, 0, 0, 1, 1, 1};
  for (const std::vector<uint32_t>& second : {std::vector<uint32_t>{0, 1, 3}, {1, 3, 0}, {3, 0, 1}}) {
    const auto overlapping = make<2>(square, {0, 1, 2, second[0], second[1], second[2]});
    const auto report = validate(overlapping, points_only(overlapping), ValidationLevel::Topology);
    EXPECT_EQ(report.count("interior-facet-sides"), 1u) << report.summary();
    EXPECT_EQ(report.count("orientation"), 0u) << report.summary();
  }
  const auto apart = make<2>(square, {0, 1, 3, 0, 3, 2});
  EXPECT_EQ(validate(apart, points_only(apart), ValidationLevel::Topology).count("interior-facet-sides"), 0u);
  // 3D: the tetrahedra 1023 and 2104 (both positive) with 3 and 4 both above the triangle 012.
  const std::vector<double> points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.2, 1, 0.3, 0.1, 2};
  const auto positive = make<3>(points, {1, 0, 2, 3, 2, 1, 0, 4});
  const auto report = validate(positive, points_only(positive), ValidationLevel::Topology);
  EXPECT_EQ(report.count("interior-facet-sides"), 1u) << report.summary();
  EXPECT_EQ(report.count("orientation"), 0u) << report.summary();
}

// A square domain bounded by notated segments (counterclockwise: the inside is the positive side).
Plc<2> notated_square() {
  Plc<2> plc;
  plc.points = {0, 0, 2, 0, 2, 2, 0, 2};
  plc.simplices = {0, 1, 1, 2, 2, 3, 3, 0};
  plc.exterior.assign(4, ExteriorSide::Negative);
  return plc;
}

TEST(Validate, FacetBoundedSquare) {
  const Plc<2> plc = notated_square();
  const auto tri = fixtures::brute_force_delaunay<2>(plc.points);  // cocircular: perturbation decides
  ASSERT_EQ(tri.num_simplices(), 2u);
  EXPECT_TRUE(validate(tri, plc).ok()) << validate(tri, plc).summary();

  Plc<2> inverted = plc;
  inverted.exterior.assign(4, ExteriorSide::Positive);
  const auto report = validate(tri, inverted);
  EXPECT_GE(report.count("domain-boundary"), 1u) << report.summary();
  EXPECT_EQ(report.count("domain-volume"), 1u) << report.summary();
}

TEST(Validate, SimplexOutsideTheDomainIsReported) {
  Plc<2> plc = notated_square();
  plc.points.insert(plc.points.end(), {1, -1});  // point 4, outside
  const auto tri = fixtures::brute_force_delaunay<2>(plc.points);
  const auto report = validate(tri, plc);
  EXPECT_GE(report.count("domain-boundary"), 1u) << report.summary();
  EXPECT_EQ(report.count("domain-volume"), 1u) << report.summary();
}

TEST(Validate, MissingTriangleLeavesDomainUncovered) {
  const Plc<2> plc = notated_square();
  auto tri = fixtures::brute_force_delaunay<2>(plc.points);
  tri.simplices.resize(3);
  compute_neighbors(tri);
  const auto report = validate(tri, plc);
  EXPECT_GE(report.count("domain-boundary"), 1u) << report.summary();
  EXPECT_EQ(report.count("domain-volume"), 1u) << report.summary();
}

TEST(Validate, MissingConstraintIsReported) {
  Plc<2> plc = notated_square();
  const auto tri = fixtures::brute_force_delaunay<2>(plc.points);
  // Constrain the diagonal the triangulation does not use.
  auto has_edge = [&](uint32_t a, uint32_t b) {
    for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
      const uint32_t* s = tri.simplex(t);
      if (std::count(s, s + 3, a) && std::count(s, s + 3, b)) return true;
    }
    return false;
  };
  ASSERT_NE(has_edge(0, 2), has_edge(1, 3));
  if (has_edge(0, 2)) plc.simplices.insert(plc.simplices.end(), {1, 3});
  else plc.simplices.insert(plc.simplices.end(), {0, 2});
  plc.exterior.push_back(ExteriorSide::None);
  const auto report = validate(tri, plc);
  EXPECT_EQ(report.count("constraints"), 1u) << report.summary();
}

TEST(Validate, SteinerPointSplittingABoundarySegment) {
  const Plc<2> plc = notated_square();
  Triangulation<2> tri;
  tri.points = plc.points;
  tri.num_input_points = 4;
  tri.points.insert(tri.points.end(), {1, 0});  // point 4, on segment 0 (0-1)
  tri.steiner_on = {0};
  tri.simplices = {0, 4, 3, 4, 1, 2, 4, 2, 3};
  compute_neighbors(tri);
  EXPECT_TRUE(validate(tri, plc, ValidationLevel::Topology).ok()) << validate(tri, plc, ValidationLevel::Topology).summary();

  tri.steiner_on = {2};  // wrong provenance
  EXPECT_EQ(validate(tri, plc, ValidationLevel::Topology).count("steiner-points"), 1u);

  tri.steiner_on = {0};
  tri.points[9] = 0x1p-60;  // just off the segment: no longer on it
  const auto report = validate(tri, plc, ValidationLevel::Topology);
  EXPECT_EQ(report.count("steiner-points"), 1u) << report.summary();
  EXPECT_EQ(report.count("constraints"), 1u) << report.summary();
}

// The cube's 8 cospherical vertices: the perturbed Delaunay triangulation (brute force), its own
// boundary notated as a facet-bounded PLC.
TEST(Validate, CosphericalCubeAsFacetBoundedDomain) {
  const Plc<3> cube = fixtures::unit_cube_surface();
  const auto tri = fixtures::brute_force_delaunay<3>(cube.points);
  ASSERT_GE(tri.num_simplices(), 5u);
  EXPECT_TRUE(validate(tri, points_only(tri)).ok()) << validate(tri, points_only(tri)).summary();

  Plc<3> plc = points_only(tri);
  for (std::size_t t = 0; t < tri.num_simplices(); ++t)
    for (int i = 0; i < 4; ++i) {
      if (tri.neighbors[4 * t + i] != kNone) continue;
      // Boundary facet opposite vertex i; with the apex replaced, orient > 0 means the simplex side.
      std::array<uint32_t, 4> s;
      std::copy_n(tri.simplex(t), 4, s.begin());
      std::array<uint32_t, 3> f;
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != i) f[j++] = s[k];
      // orient(f, apex) sign tells which side of f the domain is on.
      const auto side = predicates::orient<3>({tri.point(f[0]), tri.point(f[1]), tri.point(f[2]), tri.point(s[i])});
      plc.simplices.insert(plc.simplices.end(), f.begin(), f.end());
      plc.exterior.push_back(side == predicates::Sign::Positive ? ExteriorSide::Negative : ExteriorSide::Positive);
    }
  EXPECT_EQ(plc.num_simplices(), 12u);
  EXPECT_TRUE(validate(tri, plc).ok()) << validate(tri, plc).summary();
  plc.exterior[0] = plc.exterior[0] == ExteriorSide::Negative ? ExteriorSide::Positive : ExteriorSide::Negative;
  const auto report = validate(tri, plc);
  EXPECT_GE(report.count("domain-boundary"), 1u) << report.summary();
  EXPECT_EQ(report.count("domain-volume"), 1u) << report.summary();
}

TEST(Validate, RegionsMustAgreeAcrossUnconstrainedFacets) {
  auto tri = square_with_centre();
  tri.regions = {1, 1, 1, 2};
  const auto report = validate(tri, points_only(tri));
  EXPECT_EQ(report.count("regions"), 2u) << report.summary();
}

}  // namespace
