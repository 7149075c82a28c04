// validate() against brute-force perturbed Delaunay triangulations of grid points in D = 2..5:
// exact degeneracies everywhere, so this also checks that the perturbed predicates are consistent
// (an inconsistent perturbation leaves gaps or overlaps that validate() reports).
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "brute_force_delaunay.h"
#include "sweepcdt/validate.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

template <int D>
Plc<D> points_only(const std::vector<double>& points) {
  Plc<D> plc;
  plc.points = points;
  return plc;
}

template <int D>
void check_grids(int count, int grid, int seeds) {
  int tested = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(1000 * D + seed);
    const auto points = fixtures::distinct_grid_points<D>(rng, count, grid);
    auto tri = fixtures::brute_force_delaunay<D>(points);
    if (tri.num_simplices() == 0) continue;  // all points in one hyperplane
    ++tested;
    const auto plc = points_only<D>(points);
    const auto report = validate(tri, plc);
    EXPECT_TRUE(report.ok()) << "D=" << D << " seed " << seed << "\n" << report.summary();

    // Dropping a simplex must be noticed.
    auto broken = tri;
    broken.simplices.erase(broken.simplices.begin(), broken.simplices.begin() + D + 1);
    compute_neighbors(broken);
    EXPECT_FALSE(validate(broken, plc).ok()) << "D=" << D << " seed " << seed;
  }
  EXPECT_GE(tested, seeds / 2);
}

TEST(ValidateBruteForce, Grid2D) { check_grids<2>(12, 3, 20); }
TEST(ValidateBruteForce, Grid3D) { check_grids<3>(11, 2, 20); }
TEST(ValidateBruteForce, Grid4D) { check_grids<4>(10, 2, 10); }
TEST(ValidateBruteForce, Grid5D) { check_grids<5>(10, 1, 6); }

// The cube's and hypercube's vertices: every subset of D+2 is cospherical.
TEST(ValidateBruteForce, HypercubeVertices) {
  std::vector<double> points;
  for (int i = 0; i < 16; ++i)
    for (int k = 0; k < 4; ++k) points.push_back((i >> k) & 1);
  const auto tri = fixtures::brute_force_delaunay<4>(points);
  const auto report = validate(tri, points_only<4>(points));
  EXPECT_TRUE(report.ok()) << report.summary();
}

}  // namespace
