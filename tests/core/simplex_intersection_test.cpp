// The orientation-based intersection tests of D = 2, 3 (and the shortcuts of D = 4, 5) against the
// exact linear program, on grid inputs where touching, collinear and coplanar contacts are the rule.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "simplex_intersection.h"
#include "sweepcdt/predicates/orientation.h"

using namespace sweepcdt;

namespace {

template <int D>
bool degenerate(const std::array<const double*, D>& f) {
  for (int drop = 0; drop < D; ++drop)
    if (predicates::orient_projected<D>(f, drop) != predicates::Sign::Zero) return false;
  return true;
}

// Random pairs of simplices on `points` (D coordinates each), sharing vertices often.
template <int D>
void compare_with_lp_on(const std::vector<double>& points, int cases, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const uint32_t count = static_cast<uint32_t>(points.size() / D);
  std::uniform_int_distribution<uint32_t> pick(0, count - 1);
  int improper = 0, tested = 0;
  while (tested < cases) {
    std::array<uint32_t, D> ia, ib;
    std::array<const double*, D> a, b;
    for (int i = 0; i < D; ++i) ia[i] = pick(rng), a[i] = &points[D * ia[i]];
    for (int i = 0; i < D; ++i) {
      ib[i] = (rng() % 3 == 0) ? ia[rng() % D] : pick(rng);  // share vertices often
      b[i] = &points[D * ib[i]];
    }
    auto sa = ia, sb = ib;
    std::sort(sa.begin(), sa.end());
    std::sort(sb.begin(), sb.end());
    if (std::adjacent_find(sa.begin(), sa.end()) != sa.end() || std::adjacent_find(sb.begin(), sb.end()) != sb.end()) continue;
    if (sa == sb || degenerate<D>(a) || degenerate<D>(b)) continue;
    ++tested;
    const bool fast = detail::improper_intersection<D>(a, ia, b, ib);
    const bool lp = detail::improper_intersection_lp<D>(a, ia, b, ib);
    improper += lp;
    if (fast != lp) {
      std::string s;
      for (int i = 0; i < D; ++i) s += " a" + std::to_string(ia[i]) + "/b" + std::to_string(ib[i]);
      ADD_FAILURE() << "fast " << fast << " lp " << lp << " ids" << s;
    }
  }
  // Both outcomes must be well represented, or the comparison says little.
  EXPECT_GT(improper, cases / 20);
  EXPECT_LT(improper, cases - cases / 20);
}

template <int D>
void compare_with_lp(int grid, int cases, uint64_t seed) {
  std::vector<double> points;
  int count = 1;
  for (int k = 0; k < D; ++k) count *= grid;
  for (int i = 0; i < count; ++i)
    for (int k = 0, r = i; k < D; ++k, r /= grid) points.push_back(r % grid);
  compare_with_lp_on<D>(points, cases, seed);
}

// Every triangle in one plane (a 5 x 5 grid on it): the coplanar pairs of flat CAD faces, which have
// a 2D test of their own (separating edges), with and without shared vertices.
void compare_coplanar_with_lp(bool oblique, int cases, uint64_t seed) {
  std::vector<double> points;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) points.insert(points.end(), {double(i), double(j), oblique ? 2.0 * i - 3.0 * j + 1 : 7.0});
  compare_with_lp_on<3>(points, cases, seed);
}

TEST(SimplexIntersection, Segments2DAgreeWithLp) { compare_with_lp<2>(4, 3000, 1); }
TEST(SimplexIntersection, Triangles3DAgreeWithLp) { compare_with_lp<3>(3, 3000, 2); }
TEST(SimplexIntersection, CoplanarTrianglesAgreeWithLp) {
  compare_coplanar_with_lp(false, 3000, 5);
  compare_coplanar_with_lp(true, 3000, 6);
}
// D >= 4: the shortcuts before the linear program (disjoint boxes, one side of a hyperplane).
TEST(SimplexIntersection, Simplices4DAgreeWithLp) { compare_with_lp<4>(3, 1500, 3); }
TEST(SimplexIntersection, Simplices5DAgreeWithLp) { compare_with_lp<5>(3, 800, 4); }

TEST(SimplexIntersection, PointInSimplexMatchesLp4D) {
  const std::array<double, 16> f = {0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0};
  const std::array<const double*, 4> fc = {&f[0], &f[4], &f[8], &f[12]};
  const double inside[4] = {0.5, 0.5, 0.5, 0}, on_edge[4] = {1, 0, 0, 0}, off[4] = {0.5, 0.5, 0.5, 1e-300},
               beyond[4] = {1, 1, 0.5, 0};
  EXPECT_TRUE(detail::point_in_simplex<4>(inside, fc));
  EXPECT_TRUE(detail::point_in_simplex<4>(on_edge, fc));
  EXPECT_FALSE(detail::point_in_simplex<4>(off, fc));
  EXPECT_FALSE(detail::point_in_simplex<4>(beyond, fc));
}

}  // namespace
