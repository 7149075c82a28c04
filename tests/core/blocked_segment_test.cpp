// segment_in_spheres() (core/src/edit/blocked_segment.h): whether some sphere through a and b holds
// none of the other points, under the §6 perturbation. The oracle is the Delaunay tetrahedralization
// of all the points (delaunay.h, itself tested against the sweep sphere): ab must be one of its
// edges exactly when the answer is Delaunay. Random points, points around a segment like a Steiner
// point's star, and integer grids and cospherical points, where many lie in one plane with a and b
// and on common spheres (the perturbation decides there). Undecided is allowed only when every point
// lies in one plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "delaunay/delaunay.h"
#include "edit/blocked_segment.h"

using namespace sweepcdt;
using detail::SegmentInSpheres;

namespace {

// Points 0 and 1 are a and b; perturbation ids are the indices, as in the Delaunay triangulation.
bool is_delaunay_edge(const std::vector<double>& points) {
  for (const auto& t : detail::delaunay_simplices<3>(points))
    if (std::count(t.begin(), t.end(), 0u) && std::count(t.begin(), t.end(), 1u)) return true;
  return false;
}

SegmentInSpheres answer_for(const std::vector<double>& points, std::array<uint32_t, 3>* witness = nullptr) {
  std::vector<predicates::Vertex> others;
  for (uint32_t i = 2; i < points.size() / 3; ++i) others.push_back({points.data() + 3 * i, i});
  const detail::BlockedSegment r = detail::segment_in_spheres({points.data(), 0}, {points.data() + 3, 1}, others);
  if (witness) *witness = r.witness;
  return r.answer;
}

struct Tally {
  int delaunay = 0, blocked = 0, undecided = 0;
};

// Compares one point set's answer with the oracle (and a blocked answer's witness with the points given).
void check(const std::vector<double>& points, Tally& tally, const std::string& what) {
  std::array<uint32_t, 3> witness;
  const SegmentInSpheres answer = answer_for(points, &witness);
  if (answer == SegmentInSpheres::Undecided) {
    ++tally.undecided;
    return;
  }
  ASSERT_EQ(answer == SegmentInSpheres::Delaunay, is_delaunay_edge(points)) << what;
  if (answer == SegmentInSpheres::Delaunay) {
    ++tally.delaunay;
    return;
  }
  ++tally.blocked;
  // The witness names points given (a, b and those three alone need not be blocked: the last line's
  // bounds come from all the points seen).
  for (const uint32_t w : witness) EXPECT_LT(w, points.size() / 3 - 2) << what;
}

// n points around the segment from (-1,0,0) to (1,0,0): on a ring of radius r about its midpoint's
// axis with some spread, like the vertices of a Steiner point's star.
std::vector<double> ring(std::mt19937_64& rng, int n, double r) {
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), along(-1.5, 1.5), spread(0.5, 1.5);
  std::vector<double> points{-1, 0, 0, 1, 0, 0};
  for (int i = 0; i < n; ++i) {
    const double t = angle(rng), s = r * spread(rng);
    points.insert(points.end(), {along(rng), s * std::cos(t), s * std::sin(t)});
  }
  return points;
}

}  // namespace

TEST(BlockedSegment, AgreesWithTheDelaunayTetrahedralizationOnRandomPoints) {
  Tally tally;
  for (int seed = 0; seed < 400; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const int n = 3 + seed % 40;
    std::vector<double> points;
    for (int i = 0; i < 3 * (n + 2); ++i) points.push_back(u(rng));
    check(points, tally, "random seed " + std::to_string(seed));
  }
  for (int seed = 0; seed < 400; ++seed) {
    std::mt19937_64 rng(1000 + seed);
    check(ring(rng, 4 + seed % 30, std::ldexp(1.0, seed % 5 - 2)), tally, "ring seed " + std::to_string(seed));
  }
  EXPECT_EQ(tally.undecided, 0);
  EXPECT_GT(tally.delaunay, 100);
  EXPECT_GT(tally.blocked, 100);
}

TEST(BlockedSegment, AgreesWhereItDecidesOnGridsAndSpheres) {
  Tally tally;
  // Integer grids: a and b two grid points, the others a random subset of the rest.
  for (int seed = 0; seed < 300; ++seed) {
    std::mt19937_64 rng(2000 + seed);
    std::vector<std::array<double, 3>> grid;
    for (int x = 0; x < 4; ++x)
      for (int y = 0; y < 4; ++y)
        for (int z = 0; z < 3; ++z) grid.push_back({double(x), double(y), double(z)});
    std::shuffle(grid.begin(), grid.end(), rng);
    const std::size_t n = 6 + seed % 30;
    std::vector<double> points;
    for (std::size_t i = 0; i < n; ++i) points.insert(points.end(), grid[i].begin(), grid[i].end());
    check(points, tally, "grid seed " + std::to_string(seed));
  }
  // Exactly cospherical: the integer points at distance 5 and 3 from the origin, a and b among them.
  std::vector<std::array<double, 3>> sphere;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      for (int z = -5; z <= 5; ++z)
        if (x * x + y * y + z * z == 25 || x * x + y * y + z * z == 9) sphere.push_back({double(x), double(y), double(z)});
  for (int seed = 0; seed < 300; ++seed) {
    std::mt19937_64 rng(3000 + seed);
    std::shuffle(sphere.begin(), sphere.end(), rng);
    const std::size_t n = 6 + seed % 40;
    std::vector<double> points;
    for (std::size_t i = 0; i < n; ++i) points.insert(points.end(), sphere[i].begin(), sphere[i].end());
    check(points, tally, "sphere seed " + std::to_string(seed));
  }
  EXPECT_GT(tally.delaunay, 50);
  EXPECT_GT(tally.blocked, 50);
  EXPECT_EQ(tally.undecided, 0);
  std::cout << "[ grids, spheres ] " << tally.delaunay << " Delaunay, " << tally.blocked << " blocked, " << tally.undecided
            << " undecided\n";
}
