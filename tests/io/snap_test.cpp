// snap_coordinates() (sweepcdt/io/snap.h): the opt-in repair of CAD rounding noise. What moves, to
// what, by how much at most, and what it does to welding and to the surface checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "io_test_util.h"
#include "surface_builders.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/snap.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/write_surface.h"

namespace sweepcdt::io {
namespace {

using testing::cube_soup;

// The unit cube, welded, with the bottom face's point `noisy` moved to z = `z`.
Surface noisy_cube(uint32_t noisy, double z) {
  Surface s = weld(cube_soup());
  EXPECT_EQ(s.points[3 * noisy + 2], 0.0);
  s.points[3 * noisy + 2] = z;
  return s;
}

uint32_t bottom_point(const Surface& s) {
  for (uint32_t i = 0; i < s.num_points(); ++i)
    if (s.points[3 * i + 2] == 0 && s.points[3 * i] == 1 && s.points[3 * i + 1] == 1) return i;
  ADD_FAILURE() << "no point (1, 1, 0)";
  return 0;
}

TEST(Snap, NoiseOnAFlatFaceBecomesTheFacesValue) {
  const uint32_t p = bottom_point(weld(cube_soup()));
  const Surface noisy = noisy_cube(p, -5.077714e-17);
  SnapReport report;
  const Surface snapped = snap_coordinates(noisy, 1e-12, report);
  EXPECT_DOUBLE_EQ(report.tolerance, 1e-12 * std::sqrt(3.0));
  EXPECT_EQ(snapped.points[3 * p + 2], 0.0);  // three of the four bottom points say 0
  EXPECT_EQ(report.coordinates_moved, 1u);
  EXPECT_EQ(report.points_moved, 1u);
  EXPECT_EQ(report.points_merged, 0u);
  EXPECT_EQ(report.edges_flattened, 1u);  // the bottom face's diagonal
  EXPECT_EQ(report.largest_move, 5.077714e-17);
  EXPECT_EQ(snapped.triangles, noisy.triangles);
  // Everything else is untouched, bit for bit.
  for (std::size_t k = 0; k < noisy.points.size(); ++k)
    if (k != 3 * p + 2) EXPECT_EQ(snapped.points[k], noisy.points[k]) << k;
  // And the bottom face is exactly flat again: its two triangles are exactly coplanar.
  EXPECT_TRUE(inspect(snapped).valid());
}

TEST(Snap, TiesGoToTheValueOfLeastMagnitude) {
  // Two points at 1e-17 and two at -1e-17 (at z): one cluster with a tie; 0 is not among them, so
  // the representative is one of the values, the smaller of the two of equal magnitude.
  Surface s = weld(cube_soup());
  int changed = 0;
  for (uint32_t i = 0; i < s.num_points(); ++i)
    if (s.points[3 * i + 2] == 0) s.points[3 * i + 2] = changed++ % 2 ? 1e-17 : -1e-17;
  ASSERT_EQ(changed, 4);
  SnapReport report;
  const Surface snapped = snap_coordinates(s, 1e-12, report);
  for (uint32_t i = 0; i < snapped.num_points(); ++i)
    if (snapped.points[3 * i + 2] != 1) EXPECT_EQ(snapped.points[3 * i + 2], -1e-17) << i;
  EXPECT_EQ(report.points_moved, 2u);
}

TEST(Snap, ValuesFartherApartThanTheToleranceStay) {
  const Surface noisy = noisy_cube(bottom_point(weld(cube_soup())), 1e-6);
  SnapReport report;
  const Surface snapped = snap_coordinates(noisy, 1e-12, report);
  EXPECT_EQ(snapped.points, noisy.points);
  EXPECT_EQ(report.coordinates_moved, 0u);
  EXPECT_EQ(report.edges_flattened, 0u);
}

TEST(Snap, ZeroToleranceChangesNothingAndBadTolerancesThrow) {
  const Surface noisy = noisy_cube(bottom_point(weld(cube_soup())), 1e-17);
  SnapReport report;
  EXPECT_EQ(snap_coordinates(noisy, 0, report).points, noisy.points);
  EXPECT_EQ(report.points_moved, 0u);
  EXPECT_THROW(snap_coordinates(noisy, -1e-12, report), std::invalid_argument);
  EXPECT_THROW(snap_coordinates(noisy, std::nan(""), report), std::invalid_argument);
  EXPECT_THROW(snap_coordinates(noisy, INFINITY, report), std::invalid_argument);
}

// Greedy clusters never stretch: on random values with chains of close neighbours, no coordinate
// moves by more than the tolerance, and values in one cluster end equal.
TEST(Snap, NothingMovesByMoreThanTheTolerance) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> step(0, 2e-12);
  Soup soup;
  soup.file = "chain";
  double z = 0;
  for (uint32_t i = 0; i < 300; ++i) {
    soup.points.insert(soup.points.end(), {i * 1e-3, double(i % 2) + 2, z});  // distinct x: no point meets another
    z += step(rng);
    if (i % 50 == 49) z += 1;  // a gap: a new cluster must start
  }
  for (uint32_t i = 0; i + 2 < 300; i += 3) soup.triangles.insert(soup.triangles.end(), {i, i + 1, i + 2});
  const Surface surface = weld(soup);
  SnapReport report;
  const Surface snapped = snap_coordinates(surface, 1e-12, report);
  ASSERT_GT(report.coordinates_moved, 50u);
  ASSERT_EQ(report.points_merged, 0u);
  EXPECT_LE(report.largest_move, report.tolerance);
  for (uint32_t i = 0; i < surface.num_points(); ++i)
    EXPECT_LE(std::abs(snapped.points[3 * i + 2] - surface.points[3 * i + 2]), report.tolerance) << i;
}

TEST(Snap, PointsThatMeetAreWeldedAndACollapsedTriangleIsReported) {
  // Two tetrahedra's corners 1e-15 apart: snapped together, the two points become one.
  Soup soup;
  soup.file = "two";
  testing::add_tetrahedron(soup, 0, 0, 0);
  testing::add_tetrahedron(soup, 1 + 1e-15, 1e-15, 1e-15);  // its corner meets the first's (1, 0, 0)
  const Surface surface = weld(soup);
  ASSERT_EQ(surface.num_points(), 8u);
  SnapReport report;
  const Surface snapped = snap_coordinates(surface, 1e-12, report);
  EXPECT_EQ(report.points_merged, 1u);
  EXPECT_EQ(snapped.num_points(), 7u);
  EXPECT_EQ(snapped.num_triangles(), surface.num_triangles());
  // The bodies now touch at that vertex: inspect() reports the pinch, it is not hidden.
  EXPECT_TRUE(inspect(surface).valid());
  EXPECT_GE(inspect(snapped).count(SurfaceProblemKind::NonManifoldVertex), 1u);

  // A sliver triangle thinner than the tolerance collapses and inspect() says so.
  Soup sliver = cube_soup();
  sliver.file = "sliver";
  sliver.points.insert(sliver.points.end(), {0, 0, 5, 1, 0, 5, 0.5, 1e-14, 5});
  sliver.triangles.insert(sliver.triangles.end(), {8, 9, 10});
  const Surface thin = weld(sliver);
  ASSERT_EQ(thin.num_points(), 11u);
  const SurfaceReport before = inspect(thin);
  const SurfaceReport after = inspect(snap_coordinates(thin, 1e-12, report));
  EXPECT_EQ(before.count(SurfaceProblemKind::DegenerateTriangle), 0u);
  EXPECT_EQ(after.count(SurfaceProblemKind::DegenerateTriangle), 1u);
}

// import_plc() with a tolerance snaps before its checks, and reports it; without, the file is exact.
TEST(Snap, ImportPlcSnapsWhenAsked) {
  const testing::TempDir dir;
  const Surface noisy = noisy_cube(bottom_point(weld(cube_soup())), 3e-17);
  const auto file = dir.path() / "noisy.off";
  write_surface(file, to_plc(noisy, inspect(noisy)), Format::Off);
  SnapReport report;
  EXPECT_EQ(import_plc(file).points, noisy.points);
  const Plc<3> plc = import_plc(file, 1e-12, &report);
  EXPECT_EQ(report.points_moved, 1u);
  EXPECT_EQ(report.largest_move, 3e-17);
  EXPECT_EQ(std::count(plc.points.begin(), plc.points.end(), 3e-17), 0);
  EXPECT_EQ(plc.points.size(), noisy.points.size());
}

}  // namespace
}  // namespace sweepcdt::io
