// DDApprox: a double-double value (hi + lo) that bounds its own error — the second filter stage,
// between the double filter (approx.h) and the exact integers (arith.h), as Shewchuk's adaptive
// predicates have one. It decides the signs that are tiny beside their terms but not zero: the
// orientations and insphere tests of points on facets bent by rounding (a few ulps off one plane),
// which otherwise went to 8-limb integers (44% of a deletion pass on such a part).
//
// Bound: approx.h's argument with the unit roundoff u = 2^-53 replaced by the relative error of one
// double-word operation on normalized double-words: at most 3u^2 for a sum (AccurateDWPlusDW) and
// 4u^2 for a product (DWTimesDW3, with FMA) — Joldes, Muller and Popescu, "Tight and rigorous error
// bounds for basic building blocks of double-word arithmetic", ACM TOMS 44 (2017) — both below
// eps = 2^-103. A difference of two inputs is exact (TwoSum). So |computed - exact| <= gamma_k M with
// gamma_k = k eps / (1 - k eps), M <= mag (1 + k u) as in approx.h (mag is the same double
// computation), hence the bound 2 k eps mag. Admission and underflow as in approx.h (differences
// up to 2^64, else mag is +inf), with the absolute term for underflow raised to 2^-300: a
// double-word operation is about 20 double operations, so at most 2^17 of them, each adding at most
// 2^-1075 when it underflows, amplified by at most 11 factors below 2^64: 2^-1075+17+704 < 2^-300.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>

#include "approx.h"
#include "sweepcdt/predicates/sign.h"

namespace sweepcdt::predicates::detail {

struct DDApprox {
  double hi = 0.0, lo = 0.0;  // normalized: |lo| <= ulp(hi) / 2
  double mag = 0.0;
  int rounds = 0;

  // Knuth's TwoSum: s + e == a + b exactly.
  static void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bb = s - a;
    e = (a - (s - bb)) + (b - bb);
  }
  // |a| >= |b| (or a == 0): s + e == a + b exactly.
  static void fast_two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    e = b - (s - a);
  }
  static DDApprox add(const DDApprox& x, const DDApprox& y, double mag) {  // AccurateDWPlusDW
    double sh, sl, th, tl, vh, vl, zh, zl;
    two_sum(x.hi, y.hi, sh, sl);
    two_sum(x.lo, y.lo, th, tl);
    fast_two_sum(sh, sl + th, vh, vl);
    fast_two_sum(vh, tl + vl, zh, zl);
    return {zh, zl, mag, std::max(x.rounds, y.rounds) + 1};
  }
  friend DDApprox operator+(const DDApprox& a, const DDApprox& b) { return add(a, b, a.mag + b.mag); }
  friend DDApprox operator-(const DDApprox& a, const DDApprox& b) { return add(a, -b, a.mag + b.mag); }
  friend DDApprox operator*(const DDApprox& x, const DDApprox& y) {  // DWTimesDW3
    const double ch = x.hi * y.hi;
    const double cl1 = std::fma(x.hi, y.hi, -ch);
    const double tl1 = std::fma(x.hi, y.lo, x.lo * y.lo);
    const double cl3 = cl1 + std::fma(x.lo, y.hi, tl1);
    double zh, zl;
    fast_two_sum(ch, cl3, zh, zl);
    return {zh, zl, x.mag * y.mag, x.rounds + y.rounds + 1};
  }
  DDApprox operator-() const { return {-hi, -lo, mag, rounds}; }
};

constexpr double kDoubleWordRoundoff = 0x1p-103;
constexpr double kDoubleWordUnderflowBound = 0x1p-300;

struct DDFilterArith {
  using T = DDApprox;
  static T diff(double a, double b) {
    T d;
    DDApprox::two_sum(a, -b, d.hi, d.lo);
    const double m = std::fabs(d.hi);
    d.mag = m <= kMaxFilteredDifference ? m : INFINITY;  // NaN-safe, as approx_difference
    d.rounds = 1;  // exact (TwoSum), counted as approx.h counts a rounded difference: only a looser bound
    return d;
  }
  static T one() { return {1.0, 0.0, 1.0, 0}; }
};

// The sign of the exact value if the double-word filter can certify it.
inline std::optional<Sign> certain_sign(const DDApprox& a) {
  const double bound = (2.0 * a.rounds * kDoubleWordRoundoff) * a.mag + kDoubleWordUnderflowBound;
  // hi + lo has hi's sign and |hi + lo| >= |hi| (1 - 2^-53); the factor below rounds down at worst.
  const double least = std::fabs(a.hi) * (1.0 - 0x1p-52);
  if (!(least > bound)) return std::nullopt;  // NaN: no certificate
  return a.hi > 0 ? Sign::Positive : Sign::Negative;
}

}  // namespace sweepcdt::predicates::detail
