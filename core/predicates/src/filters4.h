// The hand-written 4D filters (as filters3.h for 3D): the orient and insphere determinants of
// differences by their 2x2 minors, in doubles, with a certified error bound. The generic filter
// (FilterArith, approx.h) tracks a magnitude and a rounding count through every operation of a
// Laplace expansion over row subsets; in the 4D sweeps it was half of the time.
#pragma once
#include <algorithm>
#include <utility>

#include "filters3.h"

namespace sweepcdt::predicates::detail {

// The 2x2 minors of columns (0, 1) and (2, 3) of N rows of 4 differences, for every row pair i < j;
// det4() combines them into the determinant of any four of the rows.
template <int N>
struct PairMinors {
  double m01[N][N], m23[N][N];

  explicit PairMinors(const double (&d)[N][4]) {
    for (int i = 0; i < N; ++i)
      for (int j = i + 1; j < N; ++j) {
        m01[i][j] = d[i][0] * d[j][1] - d[j][0] * d[i][1];
        m23[i][j] = d[i][2] * d[j][3] - d[j][2] * d[i][3];
      }
  }

  // The determinant of rows r[0] < r[1] < r[2] < r[3]: the sum over the row pairs (i, j) of
  // +-minor01(i, j) * minor23(the other two). Rounding counts (approx.h): differences 1; products 3;
  // 2x2 minors 4; a product of two minors 4 + 4 + 1 = 9; the six terms summed in sequence: 14.
  static constexpr int kRounds = 14;
  double det4(const int (&r)[4]) const {
    const auto term = [&](int i, int j, int k, int l) { return m01[r[i]][r[j]] * m23[r[k]][r[l]]; };
    return term(0, 1, 2, 3) - term(0, 2, 1, 3) + term(0, 3, 1, 2) + term(1, 2, 0, 3) - term(1, 3, 0, 2) + term(2, 3, 0, 1);
  }
};

// The same expansion over absolute values (the permanent of |d|, as PairMinors computes it), for the
// tighter bound.
template <int N>
struct PairPermanents {
  double a01[N][N], a23[N][N];

  explicit PairPermanents(const double (&d)[N][4]) {
    for (int i = 0; i < N; ++i)
      for (int j = i + 1; j < N; ++j) {
        a01[i][j] = std::fabs(d[i][0] * d[j][1]) + std::fabs(d[j][0] * d[i][1]);
        a23[i][j] = std::fabs(d[i][2] * d[j][3]) + std::fabs(d[j][2] * d[i][3]);
      }
  }

  double perm4(const int (&r)[4]) const {
    const auto perm = [&](int i, int j, int k, int l) { return a01[r[i]][r[j]] * a23[r[k]][r[l]]; };
    return perm(0, 1, 2, 3) + perm(0, 2, 1, 3) + perm(0, 3, 1, 2) + perm(1, 2, 0, 3) + perm(1, 3, 0, 2) + perm(2, 3, 0, 1);
  }
};

// det [p_i - p_4]_{i<4}. Bound::ColumnSums first (orientation.cpp): on points in general position it
// decides nearly every sign (all of 100000 random simplices), without the second expansion over
// absolute values that the permanent's bound needs.
template <Bound B = Bound::Permanent>
inline Estimate orient4_estimate(const Coords<5>& p) {
  double d[4][4], largest = 0.0;
  std::array<double, 4> sums{};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) {
      d[i][k] = p[i][k] - p[4][k];
      const double a = std::fabs(d[i][k]);
      largest = std::max(largest, a);
      sums[k] += a;
    }
  const double det = PairMinors<4>(d).det4({0, 1, 2, 3});
  if constexpr (B == Bound::ColumnSums) return {det, column_sums_bound(PairMinors<4>::kRounds, sums, largest)};
  return {det, error_bound(PairMinors<4>::kRounds, PairPermanents<4>(d).perm4({0, 1, 2, 3}), largest)};
}

// det [p_i - p_5, |p_i - p_5|^2]_{i<5}, expanded along the lift column: the sum of (-1)^i lift_i M_i,
// M_i the 4x4 determinant of the difference rows but i (the 2x2 minors shared). Rounding counts:
// lifts 3 (squares) + 3 (four terms in sequence) = 6; M_i 14; lift_i M_i 6 + 14 + 1 = 21; the five
// terms in sequence: 25. Bound::ColumnSums first, as for orient4_estimate.
template <Bound B = Bound::Permanent>
inline Estimate insphere4_estimate(const Coords<6>& p) {
  double d[5][4], lift[5], largest = 0.0;
  std::array<double, 5> sums{};
  for (int i = 0; i < 5; ++i) {
    for (int k = 0; k < 4; ++k) {
      d[i][k] = p[i][k] - p[5][k];
      const double a = std::fabs(d[i][k]);
      largest = std::max(largest, a);
      sums[k] += a;
    }
    lift[i] = ((d[i][0] * d[i][0] + d[i][1] * d[i][1]) + d[i][2] * d[i][2]) + d[i][3] * d[i][3];
    sums[4] += lift[i];
  }
  const auto rows_but = [](int skip, int (&r)[4]) {
    for (int i = 0, n = 0; i < 5; ++i)
      if (i != skip) r[n++] = i;
  };
  const PairMinors<5> minors(d);
  double det = 0.0;
  for (int skip = 0; skip < 5; ++skip) {
    int r[4];
    rows_but(skip, r);
    const double term = lift[skip] * minors.det4(r);  // sign (-1)^(skip + 4) = (-1)^skip
    det = skip == 0 ? term : (skip % 2 ? det - term : det + term);
  }
  if constexpr (B == Bound::ColumnSums) return {det, column_sums_bound(25, sums, largest)};
  const PairPermanents<5> permanents(d);
  double permanent = 0.0;
  for (int skip = 0; skip < 5; ++skip) {
    int r[4];
    rows_but(skip, r);
    permanent += lift[skip] * permanents.perm4(r);
  }
  return {det, error_bound(25, permanent, largest)};
}

// The hand-written filters by dimension, for code generic in D (sweep_keys.cpp).
template <int D>
inline constexpr bool kHandWrittenFilter = D == 3 || D == 4;
template <int D>
Estimate orient_estimate(const Coords<D + 1>& p) {
  if constexpr (D == 3) return orient3_estimate(p);
  else return orient4_estimate<>(p);
}
template <int D>
Estimate insphere_estimate(const Coords<D + 2>& p) {
  if constexpr (D == 3) return insphere3_estimate(p);
  else return insphere4_estimate<>(p);
}

}  // namespace sweepcdt::predicates::detail
