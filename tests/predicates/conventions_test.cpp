// Conventions of orient / insphere (signs stated in orientation.h), orient_value, orient_projected
// and the predicate statistics.
#include <cmath>

#include "predicate_test_util.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
using pr::Sign;

TEST(OrientConvention, CounterclockwiseIsPositiveIn2D) {
  const double a[] = {0, 0}, b[] = {1, 0}, c[] = {0, 1};
  EXPECT_EQ(pr::orient<2>(pr::Coords<3>{a, b, c}), Sign::Positive);
  EXPECT_EQ(pr::orient<2>(pr::Coords<3>{a, c, b}), Sign::Negative);
  EXPECT_EQ(pr::orient<2>(pr::Coords<3>{a, b, b}), Sign::Zero);
}

TEST(OrientConvention, BelowCounterclockwiseTriangleIsPositiveIn3D) {
  const double a[] = {0, 0, 0}, b[] = {1, 0, 0}, c[] = {0, 1, 0}, below[] = {0.2, 0.2, -1}, above[] = {0.2, 0.2, 1};
  EXPECT_EQ(pr::orient<3>(pr::Coords<4>{a, b, c, below}), Sign::Positive);
  EXPECT_EQ(pr::orient<3>(pr::Coords<4>{a, b, c, above}), Sign::Negative);
}

template <class T>
class Conventions : public ::testing::Test {};
TYPED_TEST_SUITE(Conventions, Dim1to5, DimName);

// With orient(p_0..p_D) > 0, insphere > 0 for a point inside the circumsphere (the centroid, and the
// circumcentre-like interior point), < 0 far away, 0 on a vertex; reversing the orientation flips it.
TYPED_TEST(Conventions, InsphereIsPositiveInsideAPositiveSimplex) {
  constexpr int D = TypeParam::value;
  std::array<Point<D>, D + 2> p{};
  for (int i = 0; i < D; ++i) p[i + 1][i] = 1.0;  // 0, e_1, ..., e_D
  pr::Coords<D + 2> c;
  for (int i = 0; i < D + 2; ++i) c[i] = p[i].data();
  pr::Coords<D + 1> s;
  std::copy(c.begin(), c.begin() + D + 1, s.begin());
  if (pr::orient<D>(s) == Sign::Negative) {
    std::swap(p[0], p[1]);
  }
  ASSERT_EQ(pr::orient<D>(s), Sign::Positive);
  ASSERT_EQ(ref::orient(vecs<D>(s)), 1);
  ASSERT_EQ(ref::orient_homogeneous(vecs<D>(s)), 1);

  p[D + 1].fill(0.5);  // the circumcentre of 0, e_1, ..., e_D
  EXPECT_EQ(pr::insphere<D>(c), Sign::Positive);
  p[D + 1].fill(1.0 / (D + 1));  // the centroid
  EXPECT_EQ(pr::insphere<D>(c), Sign::Positive);
  p[D + 1].fill(3.0);
  EXPECT_EQ(pr::insphere<D>(c), Sign::Negative);
  p[D + 1] = p[1];
  EXPECT_EQ(pr::insphere<D>(c), Sign::Zero);
  p[D + 1].fill(0.5);
  std::swap(c[0], c[1]);
  EXPECT_EQ(pr::insphere<D>(c), Sign::Negative);
}

// orient's sign equals sign det [[p_i, 1]] (the reference's second form) on grid inputs.
TYPED_TEST(Conventions, OrientMatchesHomogeneousDeterminant) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed0006 + D);
  for (int n = 0; n < 300; ++n) {
    std::array<Point<D>, D + 1> p;
    pr::Coords<D + 1> c;
    for (int i = 0; i <= D; ++i) {
      p[i] = grid_point<D>(rng, -3, 3);
      c[i] = p[i].data();
    }
    ASSERT_EQ(pr::to_int(pr::orient<D>(c)), ref::orient_homogeneous(vecs<D>(c))) << dump<D>(c);
  }
}

inline bool has_even_significand(double x) {
  int e = 0;
  const double m = std::frexp(x, &e);
  return (static_cast<int64_t>(std::ldexp(m, 53)) & 1) == 0;
}

// orient_value is the exact determinant det [p_i - p_D] rounded to the nearest double (ties to
// even), as the header promises — also when the value is subnormal or huge. A result one ulp off
// (faithful but not nearest) is counted separately from a wrong one.
TYPED_TEST(Conventions, OrientValue) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed0007 + D);
  FailureBudget budget;
  int not_nearest = 0;
  std::string example;
  for (int n = 0; n < 1000; ++n) {
    std::array<Point<D>, D + 1> p;
    pr::Coords<D + 1> c;
    for (int i = 0; i <= D; ++i) {
      p[i] = n % 2 ? random_point<D>(rng) : grid_point<D>(rng, -3, 3);
      c[i] = p[i].data();
    }
    if (n % 5 == 3 || n % 5 == 4) {  // determinants around 2^-1060 (subnormal range) or 2^1000
      const int e = (n % 5 == 3 ? -1060 : 1000) / D + uniform_int(rng, -2, 2);
      for (auto& x : p)
        for (double& xk : x) xk = std::ldexp(xk, e);
    }
    const auto v = vecs<D>(c);
    ref::Mat m(D, ref::Vec(D));
    for (int i = 0; i < D; ++i)
      for (int k = 0; k < D; ++k) m[i][k] = v[i][k] - v[D][k];
    const ref::Q exact = ref::det(m);
    const double got = pr::orient_value<D>(c);
    // The two doubles around `exact`: lo <= exact <= hi.
    const double trunc = exact.get_d();  // mpq_get_d truncates towards zero
    double lo = trunc, hi = trunc;
    if (ref::Q(trunc) < exact) hi = std::nextafter(trunc, INFINITY);
    if (ref::Q(trunc) > exact) lo = std::nextafter(trunc, -INFINITY);
    const ref::Q dlo = exact - ref::Q(lo), dhi = ref::Q(hi) - exact;
    const double nearest = dlo < dhi ? lo : dhi < dlo ? hi : has_even_significand(lo) ? lo : hi;
    if (got != lo && got != hi) {
      if (budget.fail())
        ADD_FAILURE() << "orient_value<" << D << "> = " << fmt(got) << " is not next to the exact value "
                      << exact.get_str() << "\n" << dump<D>(c);
    } else if (got != nearest) {
      if (++not_nearest == 1)
        example = "exact " + exact.get_str() + ", nearest " + fmt(nearest) + ", got " + fmt(got) + "\n" + dump<D>(c);
    }
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_EQ(not_nearest, 0) << "orient_value is faithful but not rounded to nearest in " << not_nearest
                            << " cases, e.g.\n" << example;
}

TYPED_TEST(Conventions, OrientProjected) {
  constexpr int D = TypeParam::value;
  if constexpr (D >= 2) {
    Rng rng(0x5eed0008 + D);
    for (int n = 0; n < 500; ++n) {
      std::array<Point<D>, D> p;
      pr::Coords<D> c;
      for (int i = 0; i < D; ++i) {
        p[i] = n % 2 ? random_point<D>(rng) : grid_point<D>(rng, -2, 2);
        c[i] = p[i].data();
      }
      for (int drop = 0; drop < D; ++drop) {
        std::vector<ref::Vec> q;
        for (int i = 0; i < D; ++i) {
          ref::Vec x;
          for (int k = 0; k < D; ++k)
            if (k != drop) x.push_back(ref::exact(p[i][k]));
          q.push_back(x);
        }
        ASSERT_EQ(pr::to_int(pr::orient_projected<D>(c, drop)), ref::orient(q)) << "drop " << drop << "\n"
                                                                                << dump<D>(c);
      }
    }
  }
}

// collinear(a, b, c) against the rational reference: every projection onto a coordinate plane has
// orientation zero. Half the cases are exactly collinear by construction (c = a + k (b - a) on the
// grid), some of those nudged by one ulp.
TYPED_TEST(Conventions, Collinear) {
  constexpr int D = TypeParam::value;
  if constexpr (D >= 2) {
    Rng rng(0x5eed0009 + D);
    int on_line = 0, off_line = 0;
    for (int n = 0; n < 600; ++n) {
      const Point<D> a = grid_point<D>(rng, -3, 3), b = grid_point<D>(rng, -3, 3);
      Point<D> c = grid_point<D>(rng, -3, 3);
      if (n % 2) {
        const int k = static_cast<int>(n % 7) - 2;
        for (int i = 0; i < D; ++i) c[i] = a[i] + k * (b[i] - a[i]);
        if (n % 5 == 0) c[n % D] = std::nextafter(c[n % D], 100.0);
      }
      bool expected = true;
      for (int i = 0; i < D && expected; ++i)
        for (int j = i + 1; j < D && expected; ++j) {
          const std::vector<ref::Vec> q{{ref::exact(a[i]), ref::exact(a[j])}, {ref::exact(b[i]), ref::exact(b[j])},
                                        {ref::exact(c[i]), ref::exact(c[j])}};
          expected = ref::orient(q) == 0;
        }
      ASSERT_EQ(pr::collinear<D>(a.data(), b.data(), c.data()), expected) << dump<D>(std::array<const double*, 3>{a.data(), b.data(), c.data()});
      (expected ? on_line : off_line)++;
    }
    EXPECT_GT(on_line, 100);
    EXPECT_GT(off_line, 100);
  }
}

TEST(PredicateStats, ConsistentWithBuildOption) {
  if (!pr::predicate_stats_enabled()) {
    const auto s = pr::predicate_stats();
    EXPECT_EQ(s.filtered + s.exact + s.perturbed, 0u);
    return;
  }
  pr::reset_predicate_stats();
  const double a[] = {0, 0}, b[] = {1, 1}, c[] = {2, 2}, d[] = {0, 1};
  pr::orient<2>(pr::Coords<3>{a, b, c});  // exactly zero: exact path
  pr::orient<2>(pr::Coords<3>{a, b, d});  // easy: filter
  const auto s = pr::predicate_stats();
  EXPECT_EQ(s.exact, 1u);
  EXPECT_EQ(s.filtered, 1u);
}

}  // namespace
