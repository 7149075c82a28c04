// The hand-written 4D filters (as filters3.h for 3D): the orient and insphere determinants of
// differences by their 2x2 minors, in doubles, with a certified error bound. The generic filter (FilterArith,
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

// det [p_i - p_5, |p_i - p_5|^2]_{i<5}, expanded along the lift column: sum of (-1)^i lift_i * M_i,
// M_i the 4x4 determinant of the difference rows but i, by the same 2x2-minor formula as orient4
// (the minors shared). Rounding counts: lifts 3 (squares) + 3 (four terms in sequence) = 6;
// M_i 14; lift_i * M_i 6 + 14 + 1 = 21; the five terms in sequence: 25.
inline Estimate insphere4_estimate(const Coords<6>& p) {
  double d[5][4], lift[5], largest = 0.0;
  for (int i = 0; i < 5; ++i) {
    for (int k = 0; k < 4; ++k) {
      d[i][k] = p[i][k] - p[5][k];
      largest = std::max(largest, std::fabs(d[i][k]));
    }
    lift[i] = ((d[i][0] * d[i][0] + d[i][1] * d[i][1]) + d[i][2] * d[i][2]) + d[i][3] * d[i][3];
  }
  // 2x2 minors of columns (0, 1) and (2, 3) for every row pair, and their permanents.
  double m01[5][5], m23[5][5], a01[5][5], a23[5][5];
  for (int i = 0; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j) {
      m01[i][j] = d[i][0] * d[j][1] - d[j][0] * d[i][1];
      m23[i][j] = d[i][2] * d[j][3] - d[j][2] * d[i][3];
      a01[i][j] = std::fabs(d[i][0] * d[j][1]) + std::fabs(d[j][0] * d[i][1]);
      a23[i][j] = std::fabs(d[i][2] * d[j][3]) + std::fabs(d[j][2] * d[i][3]);
    }
  double det = 0.0, permanent = 0.0;
  for (int skip = 0; skip < 5; ++skip) {
    int r[4];
    for (int i = 0, n = 0; i < 5; ++i)
      if (i != skip) r[n++] = i;
    // The 4x4 determinant of rows r[0..3], as in orient4_estimate.
    const double minor = m01[r[0]][r[1]] * m23[r[2]][r[3]] - m01[r[0]][r[2]] * m23[r[1]][r[3]] + m01[r[0]][r[3]] * m23[r[1]][r[2]] +
                         m01[r[1]][r[2]] * m23[r[0]][r[3]] - m01[r[1]][r[3]] * m23[r[0]][r[2]] + m01[r[2]][r[3]] * m23[r[0]][r[1]];
    const double minor_abs = a01[r[0]][r[1]] * a23[r[2]][r[3]] + a01[r[0]][r[2]] * a23[r[1]][r[3]] + a01[r[0]][r[3]] * a23[r[1]][r[2]] +
                             a01[r[1]][r[2]] * a23[r[0]][r[3]] + a01[r[1]][r[3]] * a23[r[0]][r[2]] + a01[r[2]][r[3]] * a23[r[0]][r[1]];
    const double term = lift[skip] * minor;  // sign (-1)^(skip + 4) = (-1)^skip
    det = skip == 0 ? term : (skip % 2 ? det - term : det + term);
    permanent += lift[skip] * minor_abs;
  }
  return {det, error_bound(25, permanent, largest)};
}

}  // namespace sweepcdt::predicates::detail
