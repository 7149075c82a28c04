// Approx: a double that carries what is needed to bound its own rounding error — the floating-point
// filter of every generic-dimension predicate.
//
// Derivation of the bound (Higham, "Accuracy and Stability of Numerical Algorithms", §3.1):
// a predicate is a polynomial in differences of input coordinates, evaluated by +, - and *. Expanded
// into monomials, each computed monomial carries at most k factors (1 + delta_j), |delta_j| <= u =
// 2^-53, where k = `rounds`: 1 for an input difference, max(k_a, k_b) + 1 for a sum, k_a + k_b + 1
// for a product. Hence |computed - exact| <= gamma_k * M, gamma_k = k u / (1 - k u), where M is the
// same expression with every input replaced by its absolute value and - by + (`mag`). `mag` is
// computed in floating point with the same k, so M <= mag (1 + gamma_k); for k u <= 1/10,
// gamma_k (1 + gamma_k) <= 1.25 k u, and the bound 2 k u mag leaves room for the rounding of the
// bound itself.
//
// Underflow: a product in the subnormal range may add an absolute error of 2^-1075, which later
// products amplify. Inputs are therefore admitted only when every difference is at most 2^64 in
// magnitude (a larger one poisons `mag` with +inf, which sends the predicate to the exact path). For
// polynomials of degree <= 12 with at most 2^12 operations — every predicate here — the amplified
// underflow error is below 2^-1075 * 2^12 * 2^(64*11) * 2^20 < 2^-400, the absolute term of the
// bound. Results within the bound (including exact zeros) go to the exact path.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>

#include "sweepcdt/predicates/sign.h"

namespace sweepcdt::predicates::detail {

struct Approx {
  double value = 0.0;
  double mag = 0.0;
  int rounds = 0;

  friend Approx operator+(const Approx& a, const Approx& b) {
    return {a.value + b.value, a.mag + b.mag, std::max(a.rounds, b.rounds) + 1};
  }
  friend Approx operator-(const Approx& a, const Approx& b) {
    return {a.value - b.value, a.mag + b.mag, std::max(a.rounds, b.rounds) + 1};
  }
  friend Approx operator*(const Approx& a, const Approx& b) {
    return {a.value * b.value, a.mag * b.mag, a.rounds + b.rounds + 1};
  }
  Approx operator-() const { return {-value, mag, rounds}; }
};

constexpr double kUnitRoundoff = 0x1p-53;
constexpr double kMaxFilteredDifference = 0x1p64;
constexpr double kUnderflowAbsoluteBound = 0x1p-400;

inline Approx approx_difference(double a, double b) {
  const double d = a - b;
  const double m = std::fabs(d);
  // NaN-safe: a non-finite or too large difference poisons the bound.
  return {d, m <= kMaxFilteredDifference ? m : INFINITY, 1};
}

// The sign of the exact value if the filter can certify it.
inline std::optional<Sign> certain_sign(const Approx& a) {
  const double bound = (2.0 * a.rounds * kUnitRoundoff) * a.mag + kUnderflowAbsoluteBound;
  if (a.value > bound) return Sign::Positive;
  if (a.value < -bound) return Sign::Negative;
  return std::nullopt;
}

}  // namespace sweepcdt::predicates::detail
