// Slab test for the ray x(t) = v + t d, t > 0, against a closed box: t must lie in
// [(lo_k - v_k) / d_k, (hi_k - v_k) / d_k] (swapped when d_k < 0) for every axis with d_k != 0, and
// lo_k <= v_k <= hi_k where d_k = 0. Parameters of different axes are compared exactly as
//   a/b < c/e  <=>  sign(a e - c b) * sign(b e) < 0,  a 2x2 determinant of coordinate differences.
#include "sweepcdt/predicates/ray_box.h"

#include <cmath>

#include "arith.h"

namespace sweepcdt::predicates {

template <int D>
bool ray_meets_box(const PlaneSweep&, const double* v, const double* lo, const double* hi) {
  if (lo[0] > v[0]) return false;
  for (int k = 1; k < D; ++k)
    if (v[k] < lo[k] || v[k] > hi[k]) return false;
  return true;
}

namespace {

// A slab parameter (bound - v_k) / (target_k - v_k) as its two coordinate differences.
struct Ratio {
  double bound, vk, target;
};

// The numerator x1 y2 - x2 y1 of p - q, x1 = p.bound - p.vk, y2 = q.target - q.vk,
// x2 = q.bound - q.vk, y1 = p.target - p.vk: a 2x2 determinant of coordinate differences.
// Filter: the same rounding count as orient2 (orientation.cpp, approx.h): differences 1, products
// 1 + 1 + 1 = 3, the subtraction 4, so |computed - exact| <= 2 * 4 u (|x1 y2| + |x2 y1|) (with the
// margin approx.h derives for the rounding of the bound itself), plus the underflow term, for
// differences of at most 2^64 in magnitude (which also excludes NaN and infinities).
constexpr double kRatioBound = 2.0 * 4 * detail::kUnitRoundoff;

Sign numerator_sign(const Ratio& p, const Ratio& q) {
  const double x1 = p.bound - p.vk, y2 = q.target - q.vk, x2 = q.bound - q.vk, y1 = p.target - p.vk;
  const double left = x1 * y2, right = x2 * y1;
  const double det = left - right;
  constexpr double kMax = detail::kMaxFilteredDifference;
  if (std::fabs(x1) <= kMax && std::fabs(y2) <= kMax && std::fabs(x2) <= kMax && std::fabs(y1) <= kMax) {  // not NaN/inf
    const double bound = kRatioBound * (std::fabs(left) + std::fabs(right)) + detail::kUnderflowAbsoluteBound;
    if (det > bound) return detail::count_filtered(), Sign::Positive;
    if (det < -bound) return detail::count_filtered(), Sign::Negative;
    // Exact-zero fast path: a difference of two finite doubles rounds to zero only if it is zero
    // (gradual underflow), so a zero factor in each product makes the exact value 0. The commonest
    // tie here: a box side through the ray's origin v (v is a vertex of the face in the box).
    if ((x1 == 0 || y2 == 0) && (x2 == 0 || y1 == 0)) return detail::count_filtered(), Sign::Zero;
  }
  return detail::exact_sign([&](auto& a) {
    return a.diff(p.bound, p.vk) * a.diff(q.target, q.vk) - a.diff(q.bound, q.vk) * a.diff(p.target, p.vk);
  });
}

// sign(p - q) for two slab parameters with positive denominators after orientation.
Sign compare(const Ratio& p, const Ratio& q) {
  const Sign num = numerator_sign(p, q);
  const Sign den_p = p.target > p.vk ? Sign::Positive : Sign::Negative;
  const Sign den_q = q.target > q.vk ? Sign::Positive : Sign::Negative;
  return num * den_p * den_q;
}

}  // namespace

template <int D>
bool ray_meets_box(const SphereSweep<D>& sweep, const double* v, const double* lo, const double* hi) {
  const double* target = sweep.delta[0];
  // The latest entry and the earliest exit over all axes; t > 0 is required, so start from t = 0
  // (entry "0 / 1") with no exit.
  bool have_entry = false, have_exit = false;
  Ratio entry{}, exit{};
  for (int k = 0; k < D; ++k) {
    if (target[k] == v[k]) {
      if (v[k] < lo[k] || v[k] > hi[k]) return false;
      continue;
    }
    const bool forward = target[k] > v[k];
    const Ratio near{forward ? lo[k] : hi[k], v[k], target[k]}, far{forward ? hi[k] : lo[k], v[k], target[k]};
    if (!have_entry || compare(near, entry) == Sign::Positive) entry = near, have_entry = true;
    if (!have_exit || compare(far, exit) == Sign::Negative) exit = far, have_exit = true;
  }
  if (!have_exit) return true;  // v = Delta_0 on every axis: degenerate, keep
  // The exit must be at t >= 0 (the numerator's sign against a positive denominator) and not
  // before the entry.
  const bool exit_ahead = (exit.target > exit.vk) ? exit.bound >= exit.vk : exit.bound <= exit.vk;
  return exit_ahead && (!have_entry || compare(entry, exit) != Sign::Positive);
}

template bool ray_meets_box<2>(const PlaneSweep&, const double*, const double*, const double*);
template bool ray_meets_box<3>(const PlaneSweep&, const double*, const double*, const double*);
template bool ray_meets_box<4>(const PlaneSweep&, const double*, const double*, const double*);
template bool ray_meets_box<5>(const PlaneSweep&, const double*, const double*, const double*);
template bool ray_meets_box<2>(const SphereSweep<2>&, const double*, const double*, const double*);
template bool ray_meets_box<3>(const SphereSweep<3>&, const double*, const double*, const double*);
template bool ray_meets_box<4>(const SphereSweep<4>&, const double*, const double*, const double*);
template bool ray_meets_box<5>(const SphereSweep<5>&, const double*, const double*, const double*);

}  // namespace sweepcdt::predicates
