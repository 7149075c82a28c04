// The hand-written 3D floating-point filters: the orient and insphere determinants in doubles, with
// a certified bound on their error (the rounding counts of approx.h, for this evaluation order).
// orientation.cpp decides signs with them; sweep_keys.cpp encloses power keys with them (each of
// those is an insphere determinant over an orient determinant), both the hot path of the sweeps.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "approx.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates::detail {

// |exact determinant - value| <= error. error is +inf when the bound does not hold: a difference of
// coordinates above kMaxFilteredDifference, or not finite (value may then be NaN).
struct Estimate {
  double value;
  double error;
};

// max(|x|) over the arguments by plain comparisons (std::fmax is a libm call here). A NaN may be
// dropped: the determinant is then NaN too, fails every comparison, and the exact stage reports it.
template <class... T>
inline double largest_magnitude(T... x) {
  double m = 0.0;
  ((m = std::fabs(x) > m ? std::fabs(x) : m), ...);
  return m;
}

// The bound's factor for a value `rounds` rounding levels deep (approx.h), and the cut-off.
inline double error_bound(int rounds, double permanent, double largest_difference) {
  if (!(largest_difference <= kMaxFilteredDifference)) return INFINITY;  // NaN too
  return 2.0 * rounds * kUnitRoundoff * permanent + kUnderflowAbsoluteBound;
}

// The bound from the column sums of |A| instead of the permanent of |A| (its expansion over absolute
// values): the permanent is at most the product of the column sums (expanding that product gives
// every permutation's term, and more), and the computed entries, sums and product differ from the
// exact ones by factors (1 + gamma_j), j a few dozen at most, which 1 + 2^-40 covers many times over.
// Cheaper than the permanent (a few additions per entry, no second expansion) and looser, by up to
// N^N / N! for like entries: the semi-static first stage of the 4D filters (filters4.h) and the
// only one in D >= 5 (filters_dd.h). When the product underflows the determinant is far below
// kUnderflowAbsoluteBound, which the bound then is, so no sign is certified wrongly.
template <std::size_t N>
inline double column_sums_bound(int rounds, const std::array<double, N>& column_sums, double largest_difference) {
  double product = 1.0;
  for (const double s : column_sums) product *= s;
  return error_bound(rounds, product * (1.0 + 0x1p-40), largest_difference);
}

// det [p_i - p_3]_{i<3}. Rounding counts: differences 1; 2x2 minors 1+1+1 = 3 then the subtraction
// 4; 3x3 determinant: 4 + 1 + 1 = 6 per term, two sequential additions: 8.
inline Estimate orient3_estimate(const Coords<4>& p) {
  const double *a = p[0], *b = p[1], *c = p[2], *d = p[3];
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  return {det, error_bound(8, permanent, largest_magnitude(adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz))};
}

// det [p_i - p_4, |p_i - p_4|^2]_{i<4}. Rounding counts: lifts 3 (square) then two additions: 5;
// 3x3 minors 8 as above; lift * minor: 5+8+1 = 14; (x - y) + (z - w): two more levels: 16.
inline Estimate insphere3_estimate(const Coords<5>& p) {
  const double* e = p[4];
  double dx[4], dy[4], dz[4], lift[4], largest = 0.0;
  for (int i = 0; i < 4; ++i) {
    dx[i] = p[i][0] - e[0];
    dy[i] = p[i][1] - e[1];
    dz[i] = p[i][2] - e[2];
    lift[i] = dx[i] * dx[i] + dy[i] * dy[i] + dz[i] * dz[i];
    largest = std::max(largest, largest_magnitude(dx[i], dy[i], dz[i]));
  }
  // 2x2 minors of the x,y columns for rows (i, j).
  auto minor2 = [&](int i, int j) { return dx[i] * dy[j] - dx[j] * dy[i]; };
  auto minor2_abs = [&](int i, int j) { return std::fabs(dx[i] * dy[j]) + std::fabs(dx[j] * dy[i]); };
  // 3x3 minors det[r_i; r_j; r_k] of the x,y,z columns, expanded along z.
  auto minor3 = [&](int i, int j, int k) { return dz[i] * minor2(j, k) - dz[j] * minor2(i, k) + dz[k] * minor2(i, j); };
  auto minor3_abs = [&](int i, int j, int k) {
    return std::fabs(dz[i]) * minor2_abs(j, k) + std::fabs(dz[j]) * minor2_abs(i, k) + std::fabs(dz[k]) * minor2_abs(i, j);
  };
  // Expansion along the lift column (rows a=0, b=1, c=2, d=3), as in Shewchuk's insphere.
  const double abc = minor3(0, 1, 2), bcd = minor3(1, 2, 3), cda = minor3(2, 3, 0), dab = minor3(3, 0, 1);
  const double det = (lift[3] * abc - lift[2] * dab) + (lift[1] * cda - lift[0] * bcd);
  const double permanent = (lift[3] * minor3_abs(0, 1, 2) + lift[2] * minor3_abs(3, 0, 1)) +
                           (lift[1] * minor3_abs(2, 3, 0) + lift[0] * minor3_abs(1, 2, 3));
  return {det, error_bound(16, permanent, largest)};
}

}  // namespace sweepcdt::predicates::detail
