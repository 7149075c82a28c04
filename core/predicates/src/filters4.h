// The hand-written 4D orientation filter (as filters3.h for 3D): the 4x4 determinant of differences
// by its 2x2 minors, in doubles, with a certified error bound. The generic filter (FilterArith,
// approx.h) tracks a magnitude and a rounding count through every operation of a Laplace expansion
// over row subsets; in the 4D sweeps it was half of the time.
#pragma once
#include "filters3.h"

namespace sweepcdt::predicates::detail {

// det [p_i - p_4]_{i<4} = sum over the row pairs (i, j) of +-minor_xy(i, j) * minor_zw(k, l), (k, l)
// the complementary pair. Rounding counts (approx.h): differences 1; products 3; 2x2 minors 4; a
// product of two minors 4 + 4 + 1 = 9; the six terms summed in sequence: 14.
inline Estimate orient4_estimate(const Coords<5>& p) {
  double d[4][4], largest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) {
      d[i][k] = p[i][k] - p[4][k];
      largest = std::max(largest, std::fabs(d[i][k]));
    }
  // 2x2 minors of columns (0, 1) and (2, 3) for rows i < j, and their permanents.
  const auto minor = [&](int i, int j, int c) { return d[i][c] * d[j][c + 1] - d[j][c] * d[i][c + 1]; };
  const auto minor_abs = [&](int i, int j, int c) { return std::fabs(d[i][c] * d[j][c + 1]) + std::fabs(d[j][c] * d[i][c + 1]); };
  const double det = minor(0, 1, 0) * minor(2, 3, 2) - minor(0, 2, 0) * minor(1, 3, 2) + minor(0, 3, 0) * minor(1, 2, 2) +
                     minor(1, 2, 0) * minor(0, 3, 2) - minor(1, 3, 0) * minor(0, 2, 2) + minor(2, 3, 0) * minor(0, 1, 2);
  const double permanent = minor_abs(0, 1, 0) * minor_abs(2, 3, 2) + minor_abs(0, 2, 0) * minor_abs(1, 3, 2) +
                           minor_abs(0, 3, 0) * minor_abs(1, 2, 2) + minor_abs(1, 2, 0) * minor_abs(0, 3, 2) +
                           minor_abs(1, 3, 0) * minor_abs(0, 2, 2) + minor_abs(2, 3, 0) * minor_abs(0, 1, 2);
  return {det, error_bound(14, permanent, largest)};
}

}  // namespace sweepcdt::predicates::detail
