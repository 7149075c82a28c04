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

// The rows of differences rows_but(skip) leaves of five: the other four, in order.
inline void rows_but(int skip, int (&r)[4]) {
  for (int i = 0, n = 0; i < 5; ++i)
    if (i != skip) r[n++] = i;
}

// det [p_i - p_4]_{i<4}, computed once, with two bounds: the column sums' (the semi-static first
// stage, orientation.cpp: on points in general position it decides nearly every sign, all of 100000
// random simplices) and, asked for only when that one cannot decide, the permanent's, which needs a
// second expansion over absolute values.
class Orient4Filter {
 public:
  explicit Orient4Filter(const Coords<5>& p) {
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) {
        d_[i][k] = p[i][k] - p[4][k];
        const double a = std::fabs(d_[i][k]);
        largest_ = std::max(largest_, a);
        sums_[k] += a;
      }
    det_ = PairMinors<4>(d_).det4({0, 1, 2, 3});
  }
  Estimate column_sums() const { return {det_, column_sums_bound(PairMinors<4>::kRounds, sums_, largest_)}; }
  Estimate permanent() const { return {det_, error_bound(PairMinors<4>::kRounds, PairPermanents<4>(d_).perm4({0, 1, 2, 3}), largest_)}; }

 private:
  double d_[4][4], largest_ = 0.0, det_;
  std::array<double, 4> sums_{};
};

// det [p_i - p_5, |p_i - p_5|^2]_{i<5}, expanded along the lift column: the sum of (-1)^i lift_i M_i,
// M_i the 4x4 determinant of the difference rows but i (the 2x2 minors shared). Rounding counts:
// lifts 3 (squares) + 3 (four terms in sequence) = 6; M_i 14; lift_i M_i 6 + 14 + 1 = 21; the five
// terms in sequence: 25. The same two bounds as Orient4Filter's.
class Insphere4Filter {
 public:
  static constexpr int kRounds = 25;
  explicit Insphere4Filter(const Coords<6>& p) {
    for (int i = 0; i < 5; ++i) {
      for (int k = 0; k < 4; ++k) {
        d_[i][k] = p[i][k] - p[5][k];
        const double a = std::fabs(d_[i][k]);
        largest_ = std::max(largest_, a);
        sums_[k] += a;
      }
      lift_[i] = ((d_[i][0] * d_[i][0] + d_[i][1] * d_[i][1]) + d_[i][2] * d_[i][2]) + d_[i][3] * d_[i][3];
      sums_[4] += lift_[i];
    }
    const PairMinors<5> minors(d_);
    for (int skip = 0; skip < 5; ++skip) {
      int r[4];
      rows_but(skip, r);
      const double term = lift_[skip] * minors.det4(r);  // sign (-1)^(skip + 4) = (-1)^skip
      det_ = skip == 0 ? term : (skip % 2 ? det_ - term : det_ + term);
    }
  }
  Estimate column_sums() const { return {det_, column_sums_bound(kRounds, sums_, largest_)}; }
  Estimate permanent() const {
    const PairPermanents<5> permanents(d_);
    double permanent = 0.0;
    for (int skip = 0; skip < 5; ++skip) {
      int r[4];
      rows_but(skip, r);
      permanent += lift_[skip] * permanents.perm4(r);
    }
    return {det_, error_bound(kRounds, permanent, largest_)};
  }

 private:
  double d_[5][4], lift_[5], largest_ = 0.0, det_ = 0.0;
  std::array<double, 5> sums_{};
};

// The permanent's bound alone, for code generic in D (below; sweep_keys.cpp: an enclosure).
inline Estimate orient4_estimate(const Coords<5>& p) { return Orient4Filter(p).permanent(); }
inline Estimate insphere4_estimate(const Coords<6>& p) { return Insphere4Filter(p).permanent(); }

// The hand-written filters by dimension, for code generic in D (sweep_keys.cpp).
template <int D>
inline constexpr bool kHandWrittenFilter = D == 3 || D == 4;
template <int D>
Estimate orient_estimate(const Coords<D + 1>& p) {
  if constexpr (D == 3) return orient3_estimate(p);
  else return orient4_estimate(p);
}
template <int D>
Estimate insphere_estimate(const Coords<D + 2>& p) {
  if constexpr (D == 3) return insphere3_estimate(p);
  else return insphere4_estimate(p);
}

}  // namespace sweepcdt::predicates::detail
