// delaunay_simplices<D> and delaunay_mesh<D> for D = 2, 4, 5 (core/src/delaunay/delaunay.h; D = 3 in
// delaunay_test.cpp) against the sweep sphere's unconstrained Delaunay triangulation: identical simplex
// sets under the §6 perturbation on random points and on integer grids (full of cospherical and
// cohyperplanar points), in several insertion orders; the mesh's neighbour links checked against the
// simplices' shared facets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>

#include "delaunay/delaunay.h"
#include "gift_wrap.h"
#include "sweep/sweep_cdt.h"
#include "sweepcdt/error.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/triangulation.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

using SimplexSet = std::set<std::vector<uint32_t>>;

template <int D>
SimplexSet sweep_delaunay(const std::vector<double>& points) {
  Plc<D> plc;
  plc.points = points;
  Options options;
  CdtStatistics stats;
  return fixtures::simplex_set(detail::sweep_cdt<D>(plc, detail::seed_simplex(plc), options, stats));
}

template <int D>
SimplexSet as_set(const std::vector<std::array<uint32_t, D + 1>>& simplices) {
  SimplexSet set;
  for (std::array<uint32_t, D + 1> s : simplices) {
    std::sort(s.begin(), s.end());
    set.insert(std::vector<uint32_t>(s.begin(), s.end()));
  }
  return set;
}

// Every simplex positive, and the links of delaunay_mesh: facet i of t and facet j of u are linked
// both ways exactly when they have the same vertices, and a facet without a link is in one simplex.
template <int D>
void expect_valid_mesh(const std::vector<double>& points, const detail::DelaunayMesh& mesh, const std::string& what) {
  const std::size_t count = mesh.tets.size() / (D + 1);
  ASSERT_EQ(mesh.neighbors.size(), mesh.tets.size()) << what;
  std::map<std::vector<uint32_t>, int> facets;
  const auto facet = [&](std::size_t t, std::size_t i) {
    std::vector<uint32_t> f;
    for (std::size_t k = 0; k <= D; ++k)
      if (k != i) f.push_back(mesh.tets[(D + 1) * t + k]);
    std::sort(f.begin(), f.end());
    return f;
  };
  for (std::size_t t = 0; t < count; ++t) {
    predicates::Coords<D + 1> x;
    for (int k = 0; k <= D; ++k) x[k] = points.data() + D * std::size_t{mesh.tets[(D + 1) * t + k]};
    ASSERT_EQ(predicates::orient<D>(x), predicates::Sign::Positive) << what << ": simplex " << t;
    for (std::size_t i = 0; i <= D; ++i) {
      ++facets[facet(t, i)];
      const uint32_t across = mesh.neighbors[(D + 1) * t + i];
      if (across == kNone) continue;
      ASSERT_EQ(mesh.neighbors[across], (D + 1) * t + i) << what << ": link not mutual";
      EXPECT_EQ(facet(across / (D + 1), across % (D + 1)), facet(t, i)) << what << ": linked facets differ";
    }
  }
  for (std::size_t t = 0; t < count; ++t)
    for (std::size_t i = 0; i <= D; ++i)
      EXPECT_EQ(facets[facet(t, i)], mesh.neighbors[(D + 1) * t + i] == kNone ? 1 : 2) << what;
}

// The default (BRIO) order, index order, reverse order and random orders all give the sweep's
// triangulation.
template <int D>
void expect_same_as_sweep(const std::vector<double>& points, const std::string& what, int random_orders = 2) {
  const SimplexSet reference = sweep_delaunay<D>(points);
  EXPECT_EQ(as_set<D>(detail::delaunay_simplices<D>(points)), reference) << what;
  const detail::DelaunayMesh mesh = detail::delaunay_mesh<D>(points);
  expect_valid_mesh<D>(points, mesh, what);
  EXPECT_EQ(mesh.tets.size(), (D + 1) * reference.size()) << what;

  const auto orders = fixtures::insertion_orders(static_cast<uint32_t>(points.size() / D), random_orders);
  for (std::size_t k = 0; k < orders.size(); ++k)
    EXPECT_EQ(as_set<D>(detail::delaunay_simplices_in_order<D>(points, orders[k])), reference) << what << " order " << k;
}

template <int D>
std::vector<double> random_points(int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<double> points(D * count);
  for (double& x : points) x = coordinate(rng);
  return points;
}

// Every point of {0..size-1}^D.
template <int D>
std::vector<double> full_grid(int size) {
  std::vector<double> points;
  std::array<int, D> x{};
  for (;;) {
    points.insert(points.end(), x.begin(), x.end());
    int k = 0;
    while (k < D && ++x[k] == size) x[k++] = 0;
    if (k == D) return points;
  }
}

// Whether all points lie in one hyperplane (exactly): every D-subset of the others spans a flat simplex
// with point 0 (the differences p_i - p_0 then have rank below D).
template <int D>
bool all_in_one_hyperplane(const std::vector<double>& points) {
  const std::size_t n = points.size() / D;
  if (n <= D) return true;
  std::vector<int> pick(D);
  for (int k = 0; k < D; ++k) pick[k] = k + 1;
  for (;;) {
    predicates::Coords<D + 1> x;
    x[0] = points.data();
    for (int k = 0; k < D; ++k) x[k + 1] = points.data() + D * std::size_t(pick[k]);
    if (predicates::orient<D>(x) != predicates::Sign::Zero) return false;
    int k = D - 1;  // the next D-subset of 1..n-1
    while (k >= 0 && pick[k] == static_cast<int>(n) - D + k) --k;
    if (k < 0) return true;
    ++pick[k];
    for (int j = k + 1; j < D; ++j) pick[j] = pick[j - 1] + 1;
  }
}

template <int D>
void random_and_grid_points(int random_count, int grid_size, int subsets) {
  for (int count : {D + 1, D + 2, 20, random_count})
    for (uint64_t seed = 0; seed < 3; ++seed)
      expect_same_as_sweep<D>(random_points<D>(count, seed), "random " + std::to_string(count) + " seed " + std::to_string(seed));
  expect_same_as_sweep<D>(full_grid<D>(2), "grid 2^D", 4);
  if (grid_size > 2) expect_same_as_sweep<D>(full_grid<D>(grid_size), "full grid");
  int compared = 0;
  for (uint64_t seed = 0; seed < static_cast<uint64_t>(subsets); ++seed) {
    std::mt19937_64 rng(seed);
    const std::vector<double> points = fixtures::distinct_grid_points<D>(rng, D + 2 + static_cast<int>(seed % 12), D == 2 ? 3 : 2);
    if (all_in_one_hyperplane<D>(points)) {
      EXPECT_THROW(detail::delaunay_simplices<D>(points), Error) << "seed " << seed;
      continue;
    }
    expect_same_as_sweep<D>(points, "grid subset seed " + std::to_string(seed), 1);
    ++compared;
  }
  EXPECT_GE(compared, subsets / 2);
}

TEST(DelaunayDD, RandomAndGridPoints2D) { random_and_grid_points<2>(2000, 12, 40); }
TEST(DelaunayDD, RandomAndGridPoints4D) { random_and_grid_points<4>(600, 3, 30); }
TEST(DelaunayDD, RandomAndGridPoints5D) { random_and_grid_points<5>(200, 2, 8); }

// Points in one hyperplane (the last coordinate a combination of the others), duplicates and a count
// that is no multiple of D are refused; D + 1 independent points are one simplex.
TEST(DelaunayDD, Throws) {
  std::vector<double> flat = random_points<4>(30, 1);
  for (std::size_t i = 0; i < flat.size(); i += 4) {
    flat[i] = std::round(100 * flat[i]), flat[i + 1] = std::round(100 * flat[i + 1]);
    flat[i + 3] = flat[i] + 2 * flat[i + 1];  // exact: small integers
  }
  EXPECT_THROW(detail::delaunay_simplices<4>(flat), Error);
  std::vector<double> duplicate = random_points<5>(10, 2);
  duplicate.insert(duplicate.end(), duplicate.begin() + 15, duplicate.begin() + 20);
  EXPECT_THROW(detail::delaunay_simplices<5>(duplicate), Error);
  EXPECT_THROW(detail::delaunay_simplices<4>({0, 0, 0, 0, 1}), Error);
  EXPECT_THROW(detail::delaunay_simplices<2>({}), Error);
  EXPECT_EQ(detail::delaunay_simplices<4>({0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}).size(), 1u);
}

}  // namespace
