// sweepcdt/steiner_point.h: is_point_on_segment() recognises exactly the points a + t (b - a) that
// refine can make, for any t — checked against a brute-force scan of the doubles t near the answer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "sweepcdt/steiner_point.h"

using namespace sweepcdt;

namespace {

// Brute force: some t within `window` doubles of t0 (in (0, 1)) gives x from a, or from b.
bool scan_near(const double* a, const double* b, const double* x, double t0, int window) {
  for (const bool reversed : {false, true}) {
    const double* from = reversed ? b : a;
    const double* to = reversed ? a : b;
    double t = reversed ? 1 - t0 : t0;
    for (int k = 0; k < window; ++k) t = std::nextafter(t, 0.0);
    for (int k = 0; k < 2 * window; ++k, t = std::nextafter(t, 1.0)) {
      if (!(t > 0 && t < 1)) continue;
      double y[3];
      point_on_segment(from, to, t, y);
      if (y[0] == x[0] && y[1] == x[1] && y[2] == x[2]) return true;
    }
  }
  return false;
}

// A random segment in [-100, 100]^3; every fifth trial's has a coordinate that does not change along it.
void random_segment(std::mt19937_64& rng, int trial, double* a, double* b) {
  std::uniform_real_distribution<double> coord(-100, 100);
  for (int k = 0; k < 3; ++k) a[k] = coord(rng), b[k] = coord(rng);
  if (trial % 5 == 0) b[trial % 3] = a[trial % 3];
}

TEST(SteinerPoint, RecognisesEveryConstructionAndNothingOffTheSegment) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> param(0.01, 0.99);
  int accepted_nudged = 0, rejected_nudged = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    double a[3], b[3], x[3];
    random_segment(rng, trial, a, b);
    const double t = param(rng);
    point_on_segment(a, b, t, x);
    ASSERT_TRUE(is_point_on_segment(a, b, x)) << trial;
    ASSERT_TRUE(is_point_on_segment(b, a, x)) << trial;  // either end first
    // One coordinate nudged by a few ulps: sometimes still the rounding of another t, sometimes not;
    // the recogniser must agree with the brute-force scan either way.
    const int k = trial % 3;
    x[k] = std::nextafter(x[k], trial % 2 ? INFINITY : -INFINITY);
    if (trial % 4 == 0) x[k] = std::nextafter(x[k], trial % 2 ? INFINITY : -INFINITY);
    const bool expected = scan_near(a, b, x, t, 1 << 12);
    ASSERT_EQ(is_point_on_segment(a, b, x), expected) << trial;
    (expected ? accepted_nudged : rejected_nudged)++;
  }
  // Both kinds occur, so the comparison above tested something each way.
  EXPECT_GT(accepted_nudged, 50);
  EXPECT_GT(rejected_nudged, 50);
}

TEST(SteinerPoint, EndsAndPointsBeyondThemAreNotSplitPoints) {
  const double a[3] = {0, 0, 0}, b[3] = {1, 2, 3};
  const double beyond[3] = {2, 4, 6}, before[3] = {-0.5, -1, -1.5}, off[3] = {0.5, 1, 1.5000001};
  EXPECT_FALSE(is_point_on_segment(a, b, a));
  EXPECT_FALSE(is_point_on_segment(a, b, b));
  EXPECT_FALSE(is_point_on_segment(a, b, beyond));
  EXPECT_FALSE(is_point_on_segment(a, b, before));
  EXPECT_FALSE(is_point_on_segment(a, b, off));
  const double mid[3] = {0.5, 1, 1.5};
  EXPECT_TRUE(is_point_on_segment(a, b, mid));
}

// The recogniser's searches alone (its first version, without the early answers it now gives when
// x is beyond what the ends of t's range give): the two must agree everywhere, near the segment's
// ends and beyond them too, where the brute-force scan above cannot reach (near t = 0 the doubles t
// are far denser than the points they give).
bool searched_from_a_to_b(const double* a, const double* b, const double* x) {
  const auto bits = [](double t) {
    uint64_t u;
    std::memcpy(&u, &t, sizeof u);
    return u;
  };
  const auto from_bits = [](uint64_t u) {
    double t;
    std::memcpy(&t, &u, sizeof t);
    return t;
  };
  uint64_t first = 1, last = bits(1.0) - 1;
  for (int k = 0; k < 3 && first <= last; ++k) {
    const double d = b[k] - a[k];
    const auto value = [&](uint64_t u) { return a[k] + from_bits(u) * d; };
    if (d == 0) {
      if (value(first) != x[k]) return false;
      continue;
    }
    const auto first_where = [&](auto&& predicate) {
      uint64_t lo = first, hi = last + 1;
      while (lo < hi) {
        const uint64_t mid = lo + (hi - lo) / 2;
        if (predicate(mid)) hi = mid;
        else lo = mid + 1;
      }
      return lo;
    };
    const uint64_t begin = first_where([&](uint64_t u) { return d > 0 ? value(u) >= x[k] : value(u) <= x[k]; });
    const uint64_t end = first_where([&](uint64_t u) { return d > 0 ? value(u) > x[k] : value(u) < x[k]; });
    if (begin >= end) return false;
    first = begin, last = end - 1;
  }
  return first <= last;
}

TEST(SteinerPoint, EarlyAnswersAgreeWithTheSearchesNearTheEndsAndBeyond) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> unit(0, 1);
  int on = 0, off = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    double a[3], b[3], x[3];
    random_segment(rng, trial, a, b);
    // t near 0, near 1, in between, or beyond an end; then x nudged by up to 3 ulps in a coordinate.
    const int regime = trial % 4;
    const double t = regime == 0 ? std::ldexp(unit(rng), -40 - trial % 13)
                     : regime == 1 ? 1 - std::ldexp(unit(rng), -40 - trial % 13)
                     : regime == 2 ? unit(rng)
                                   : (trial % 8 < 4 ? -1 : 1) * std::ldexp(unit(rng), -45) + (trial % 8 < 4 ? 0 : 1);
    point_on_segment(a, b, t, x);
    for (int nudge = trial % 4; nudge > 0; --nudge) x[trial % 3] = std::nextafter(x[trial % 3], trial % 2 ? INFINITY : -INFINITY);
    const bool expected = !(x[0] == a[0] && x[1] == a[1] && x[2] == a[2]) && !(x[0] == b[0] && x[1] == b[1] && x[2] == b[2]) &&
                          (searched_from_a_to_b(a, b, x) || searched_from_a_to_b(b, a, x));
    ASSERT_EQ(is_point_on_segment(a, b, x), expected) << trial;
    (expected ? on : off)++;
  }
  EXPECT_GT(on, 2000);
  EXPECT_GT(off, 2000);
}

// The constructions of earlier versions are special cases, so their meshes still verify: the
// midpoint a + (b - a) / 2, and a point at a power-of-two distance from an input vertex v.
TEST(SteinerPoint, OlderConstructionsAreRecognised) {
  const double v[3] = {0.1, -3.7, 12.25}, w[3] = {7.3, 2.9, -1.0 / 3};
  double mid[3], shell[3];
  for (int k = 0; k < 3; ++k) mid[k] = v[k] + (w[k] - v[k]) / 2;
  const double length = std::sqrt((w[0] - v[0]) * (w[0] - v[0]) + (w[1] - v[1]) * (w[1] - v[1]) + (w[2] - v[2]) * (w[2] - v[2]));
  const double t = std::ldexp(1.0, static_cast<int>(std::lround(std::log2(length / 2)))) / length;
  for (int k = 0; k < 3; ++k) shell[k] = v[k] + t * (w[k] - v[k]);
  EXPECT_TRUE(is_point_on_segment(v, w, mid));
  EXPECT_TRUE(is_point_on_segment(v, w, shell));
}

}  // namespace

// parameter_between (a piece split near its encroaching vertex's projection): strictly inside the
// piece, within 2^-kShellBits of it of the target, in either order of the ends; and on a segment
// with float ends (whose difference is exact) the point it gives is mostly exactly on the segment,
// a + t (b - a) without rounding, as the shells' and midpoints' points are (refine.h: no folds).
TEST(SteinerPoint, ParameterBetweenStaysInsideNearItsTargetAndOnFloatSegments) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1), coord(-100, 100);
  int exact = 0;
  const int trials = 2000;
  for (int trial = 0; trial < trials; ++trial) {
    // A piece [ta, tb] as refinement makes them: dyadic ends from halvings of [0, 1].
    const int depth = 1 + trial % 12;
    const double step = std::ldexp(1.0, -depth);
    const double ta = std::floor(unit(rng) / step) * step, tb = ta + step;
    const double fraction = 0.1 + 0.8 * unit(rng);
    for (const bool reversed : {false, true}) {
      const double from = reversed ? tb : ta, to = reversed ? ta : tb;
      const double t = parameter_between(from, to, fraction);
      ASSERT_GT(t, ta) << trial;
      ASSERT_LT(t, tb) << trial;
      ASSERT_LE(std::fabs(t - (from + fraction * (to - from))), step * 0x1p-20) << trial;
    }
    double ad[3], bd[3], x[3];  // float coordinates
    for (int k = 0; k < 3; ++k) ad[k] = static_cast<float>(coord(rng)), bd[k] = static_cast<float>(coord(rng));
    point_on_segment(ad, bd, parameter_between(ta, tb, fraction), x);
    ASSERT_TRUE(is_point_on_segment(ad, bd, x)) << trial;
    // Exact when t (b - a) needs no rounding (fma's remainder is 0) and neither does adding a (TwoSum).
    const double t = parameter_between(ta, tb, fraction);
    bool rounded = false;
    for (int k = 0; k < 3; ++k) {
      const double d = bd[k] - ad[k], product = t * d, remainder = std::fma(t, d, -product);
      const double sum = ad[k] + product, back = sum - ad[k], error = (ad[k] - (sum - back)) + (product - back);
      rounded |= remainder != 0 || error != 0;
    }
    exact += !rounded;
  }
  EXPECT_GT(exact, trials / 2) << "points on float segments mostly rounded off them";
}
