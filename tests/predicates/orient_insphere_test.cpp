// orient, insphere, orient_value and orient_projected against the rational reference, on random,
// grid (exactly degenerate), nearly degenerate (1-ulp) and extreme-scale inputs, D = 1..5.
#include <cmath>

#include "predicate_test_util.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
using pr::Sign;

template <int D>
struct OrientInsphereChecker {
  FailureBudget budget;
  int cases = 0, orient_zeros = 0, insphere_zeros = 0;

  // Checks orient on the first D+1 points and insphere on all D+2.
  void check(const std::array<Point<D>, D + 2>& pts, const char* what) {
    pr::Coords<D + 2> all;
    for (int i = 0; i < D + 2; ++i) all[i] = pts[i].data();
    pr::Coords<D + 1> simplex;
    std::copy(all.begin(), all.begin() + D + 1, simplex.begin());
    const auto v = vecs<D>(all);
    ++cases;

    const int eo = ref::orient({v.begin(), v.begin() + D + 1});
    orient_zeros += eo == 0;
    const Sign go = pr::orient<D>(simplex);
    if (pr::to_int(go) != eo && budget.fail())
      ADD_FAILURE() << what << ": orient<" << D << "> expected " << sign_name(eo) << ", got " << sign_name(go)
                    << "\n" << dump<D>(simplex);

    const int ei = ref::insphere(v);
    insphere_zeros += ei == 0;
    const Sign gi = pr::insphere<D>(all);
    if (pr::to_int(gi) != ei && budget.fail())
      ADD_FAILURE() << what << ": insphere<" << D << "> expected " << sign_name(ei) << ", got " << sign_name(gi)
                    << "\n" << dump<D>(all);
  }
};

template <class T>
class OrientInsphere : public ::testing::Test {};
TYPED_TEST_SUITE(OrientInsphere, Dim1to5, DimName);

TYPED_TEST(OrientInsphere, RandomDoubles) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed0001 + D);
  OrientInsphereChecker<D> c;
  for (int n = 0; n < 3000; ++n) {
    std::array<Point<D>, D + 2> p;
    for (auto& x : p) x = random_point<D>(rng);
    c.check(p, "random");
  }
  EXPECT_EQ(c.budget.failures, 0) << "of " << c.cases << " cases";
}

TYPED_TEST(OrientInsphere, IntegerGridDegenerate) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed0002 + D);
  OrientInsphereChecker<D> c;
  for (int n = 0; n < 4000; ++n) {
    std::array<Point<D>, D + 2> p;
    for (auto& x : p) x = grid_point<D>(rng, -2, 2);
    c.check(p, "grid");
  }
  EXPECT_EQ(c.budget.failures, 0) << "of " << c.cases << " cases";
  // The point of the grid: exact zeros must be common, so the exact paths are exercised.
  EXPECT_GT(c.orient_zeros, c.cases / 100) << "too few degenerate orient cases";
  EXPECT_GT(c.insphere_zeros, c.cases / 100) << "too few degenerate insphere cases";
}

// A double with at most 30 significant bits in [-1, 1], so small dyadic combinations are exact.
inline double short_double(Rng& rng) { return std::ldexp(uniform_int(rng, -(1 << 29), 1 << 29), -29); }

TYPED_TEST(OrientInsphere, NearlyDegenerateOneUlp) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed0003 + D);
  OrientInsphereChecker<D> c;
  for (int n = 0; n < 3000; ++n) {
    std::array<Point<D>, D + 2> p;
    const int kind = n % 3;
    if (kind == 0) {
      // Exactly on a dyadic hyperplane x_{D-1} = sum a_k x_k + b (and the sphere point likewise),
      // then one coordinate nudged by -1, 0 or +1 ulp.
      std::array<double, D> a;
      for (double& ak : a) ak = std::ldexp(uniform_int(rng, -4, 4), -2);
      for (auto& x : p) {
        double last = a[D - 1];
        for (int k = 0; k + 1 < D; ++k) {
          x[k] = short_double(rng);
          last += a[k] * x[k];
        }
        x[D - 1] = last;  // exact: 30-bit values times 3-bit dyadics, sums of few terms
      }
      auto& victim = p[uniform_int(rng, 0, D + 1)];
      const int k = uniform_int(rng, 0, D - 1);
      victim[k] = nudge(victim[k], uniform_int(rng, -1, 1));
    } else if (kind == 1) {
      // The last points as rounded affine combinations of the first ones, nudged a few ulps.
      for (int i = 0; i < D; ++i) p[i] = random_point<D>(rng);
      for (int i = D; i < D + 2; ++i) {
        for (int k = 0; k < D; ++k) {
          double x = p[0][k];
          for (int j = 1; j < D; ++j) x += 0.3 * j / D * (p[j][k] - p[0][k]);
          p[i][k] = nudge(x, uniform_int(rng, -2, 2));
        }
      }
    } else {
      // Nearly cospherical: rounded points of a sphere around a random centre, nudged.
      const Point<D> centre = random_point<D>(rng);
      const double r = uniform(rng, 0.25, 2.0);
      for (auto& x : p) {
        Point<D> g;
        double len2 = 0;
        for (double& gk : g) {
          gk = std::normal_distribution<double>()(rng);
          len2 += gk * gk;
        }
        for (int k = 0; k < D; ++k) x[k] = nudge(centre[k] + r * g[k] / std::sqrt(len2), uniform_int(rng, -1, 1));
      }
    }
    c.check(p, kind == 0 ? "dyadic hyperplane +-1ulp" : kind == 1 ? "affine combination" : "near sphere");
  }
  EXPECT_EQ(c.budget.failures, 0) << "of " << c.cases << " cases";
  EXPECT_GT(c.orient_zeros, 0);
}

TYPED_TEST(OrientInsphere, ExactlyCosphericalTranslatedAndNudged) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed0004 + D);
  OrientInsphereChecker<D> c;
  const auto sphere = integer_sphere<D>(D == 1 ? 9 : D == 2 ? 25 : D == 3 ? 9 : 4);
  ASSERT_GE(sphere.size(), 2u);
  for (int n = 0; n < 2000; ++n) {
    std::array<Point<D>, D + 2> p;
    Point<D> offset;
    for (double& o : offset) o = short_double(rng) * 64;  // dyadic: the translation stays exact
    for (auto& x : p) {
      x = sphere[uniform_int(rng, 0, static_cast<int>(sphere.size()) - 1)];
      for (int k = 0; k < D; ++k) x[k] += offset[k];
    }
    if (n % 2) {
      auto& victim = p[uniform_int(rng, 0, D + 1)];
      const int k = uniform_int(rng, 0, D - 1);
      victim[k] = nudge(victim[k], uniform_int(rng, 0, 1) ? 1 : -1);
    }
    c.check(p, n % 2 ? "cospherical, one point nudged 1 ulp" : "cospherical, translated");
  }
  EXPECT_EQ(c.budget.failures, 0) << "of " << c.cases << " cases";
  EXPECT_GT(c.insphere_zeros, c.cases / 10);
}

TYPED_TEST(OrientInsphere, ExtremeScales) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed0005 + D);
  OrientInsphereChecker<D> c;
  const int exponents[] = {-500, -1000, 60, 80, 500};
  for (int n = 0; n < 2500; ++n) {
    const int e = exponents[n % 5];
    std::array<Point<D>, D + 2> p;
    const bool random = (n / 5) % 3 == 0;
    for (auto& x : p) {
      x = random ? random_point<D>(rng) : grid_point<D>(rng, -2, 2);
      for (double& xk : x) xk = std::ldexp(xk, e);
    }
    if ((n / 5) % 3 == 2) {
      // Huge common offset with small differences: translation of the grid by 2^40 (exact).
      for (auto& x : p)
        for (double& xk : x) xk = std::ldexp(xk, -e) + 0x1p40;
    }
    c.check(p, random ? "random, scaled" : "grid, scaled or offset");
  }
  EXPECT_EQ(c.budget.failures, 0) << "of " << c.cases << " cases";
}

// Integer coordinates of every magnitude up to 2^53 with exact degeneracies: a small grid pattern
// g scaled by an integer step and translated, p = o + step * g (degenerate exactly when the pattern
// is). Exercises integer fast paths up to and across their overflow limits.
TYPED_TEST(OrientInsphere, LargeIntegersDegenerate) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed000a + D);
  OrientInsphereChecker<D> c;
  for (int n = 0; n < 3000; ++n) {
    const int bits = 8 + n % 46;  // coordinates up to about 2^bits, bits = 8..53
    auto big = [&](int b) {
      return static_cast<double>(std::uniform_int_distribution<int64_t>(-(int64_t{1} << b), int64_t{1} << b)(rng));
    };
    const double step = std::max(1.0, std::fabs(big(bits - 3)));
    Point<D> origin;
    for (double& o : origin) o = big(bits - 1);
    std::array<Point<D>, D + 2> p;
    for (auto& x : p) {
      x = grid_point<D>(rng, -2, 2);
      for (int k = 0; k < D; ++k) x[k] = origin[k] + step * x[k];  // |x| < 2^53: exact
    }
    if (n % 5 == 4) {  // break the degeneracy by one unit
      auto& victim = p[uniform_int(rng, 0, D + 1)];
      victim[uniform_int(rng, 0, D - 1)] += uniform_int(rng, 0, 1) ? 1.0 : -1.0;
    }
    c.check(p, "large integers");
  }
  EXPECT_EQ(c.budget.failures, 0) << "of " << c.cases << " cases";
  EXPECT_GT(c.orient_zeros, c.cases / 50);
}

// Scales at which the determinant's terms are subnormal (so the filter's products lose bits to
// underflow), and axes scaled very differently (so underflowed minors get multiplied by huge
// entries): the filter's absolute underflow term and its 2^64 admission limit must send these to
// the exact path.
TYPED_TEST(OrientInsphere, SubnormalAndMixedScales) {
  constexpr int D = TypeParam::value;
  Rng rng(0x5eed0009 + D);
  OrientInsphereChecker<D> c;
  for (int n = 0; n < 3000; ++n) {
    std::array<Point<D>, D + 2> p;
    for (auto& x : p) x = n % 4 == 3 ? grid_point<D>(rng, -3, 3) : random_point<D>(rng);
    std::array<int, D> e;
    const int kind = n % 3;
    if (kind == 0) {
      e.fill(-1074 / D + uniform_int(rng, -1, 2));  // orient's D-fold products near 2^-1074
    } else if (kind == 1) {
      e.fill(-1074 / (D + 2) + uniform_int(rng, -1, 2));  // insphere's (D+2)-fold products
    } else if (D >= 3) {
      // The leading 2x2 minors (axes 0, 1) are subnormal, then multiplied by a last axis of 2^700+.
      e.fill(0);
      e[0] = -537 + uniform_int(rng, -2, 2);
      e[1] = -537 + uniform_int(rng, -2, 2);
      e[D - 1] = uniform_int(rng, 700, 1000);
    } else {
      for (int k = 0; k < D; ++k) e[k] = k == 0 ? uniform_int(rng, 100, 400) : uniform_int(rng, -900, -300);
    }
    for (auto& x : p)
      for (int k = 0; k < D; ++k) x[k] = std::ldexp(x[k], e[k]);
    c.check(p, kind == 0 ? "orient terms subnormal" : kind == 1 ? "insphere terms subnormal" : "mixed axis scales");
  }
  EXPECT_EQ(c.budget.failures, 0) << "of " << c.cases << " cases";
}

}  // namespace
