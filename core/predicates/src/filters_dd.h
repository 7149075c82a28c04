// A semi-static floating-point filter for orient and insphere in D >= 5, where no hand-written one
// exists (filters3.h, filters4.h): the determinant in doubles by the generic expansion (arith.h's
// determinant<N> with T = double), and a bound computed from the matrix's column sums instead of
// carried through every operation as the generic filter (approx.h) does.
//
// Why the bound holds: approx.h bounds the error by gamma_k M, where k is the expansion's rounding
// depth and M the same expansion over absolute values: the permanent of |A| for the exact entries A.
// The permanent is at most the product of the column sums of |A| (expanding that product gives every
// permutation's term, and more). The computed entries and sums differ from the exact ones by factors
// (1 + gamma_j), j <= 2D + 2 (at most 12 roundings per entry and sum, 6 for the product), which the
// factor 1 + 2^-40 covers many times over; and gamma_k <= 1.25 k u < 2 k u. k depends on the
// expansion's shape only, so it is found once by running the expansion on Approx values.
// The column sums overestimate M by up to N^N / N! (65x for a 6x6 matrix of like entries): a filter
// that fails more often near degeneracy, which only costs the generic filter and the exact stage.
#pragma once
#include <array>
#include <cmath>

#include "approx.h"
#include "arith.h"
#include "filters3.h"  // Estimate, error_bound
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates::detail {

// The rounding depth of determinant<N> when column j's entries are `column_rounds[j]` deep.
template <int N>
int determinant_rounds(const std::array<int, N>& column_rounds) {
  std::array<Approx, N * N> m;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) m[i * N + j] = {1.0, 1.0, column_rounds[j]};
  return determinant<N>(m).rounds;
}

template <int N>
Estimate matrix_estimate(const std::array<double, N * N>& m, const std::array<double, N>& column_sums, int rounds,
                         double largest_difference) {
  double product = 1.0;
  for (const double s : column_sums) product *= s;
  return {determinant<N>(m), error_bound(rounds, product * (1.0 + 0x1p-40), largest_difference)};
}

// det [p_i - p_D]_{i<D}, as orient_det (arith.h).
template <int D>
Estimate orient_estimate_dd(const Coords<D + 1>& p) {
  static const int rounds = [] {
    std::array<int, D> columns;
    columns.fill(1);
    return determinant_rounds<D>(columns);
  }();
  std::array<double, D * D> m;
  std::array<double, D> sums{};
  double largest = 0.0;
  for (int i = 0; i < D; ++i)
    for (int k = 0; k < D; ++k) {
      const double d = p[i][k] - p[D][k], a = std::fabs(d);
      m[i * D + k] = d;
      sums[k] += a;
      largest = a > largest ? a : largest;
    }
  return matrix_estimate<D>(m, sums, rounds, largest);
}

// det [p_i - p_{D+1}, |p_i - p_{D+1}|^2]_{i<=D}, as the generic insphere formula (orientation.cpp).
template <int D>
Estimate insphere_estimate_dd(const Coords<D + 2>& p) {
  constexpr int N = D + 1;
  static const int rounds = [] {
    std::array<int, N> columns;
    columns.fill(1);
    columns[D] = 3 + (D - 1);  // d*d: 3 deep; each further + d*d one more
    return determinant_rounds<N>(columns);
  }();
  std::array<double, N * N> m;
  std::array<double, N> sums{};
  double largest = 0.0;
  for (int i = 0; i <= D; ++i) {
    double lift = 0.0;
    for (int k = 0; k < D; ++k) {
      const double d = p[i][k] - p[D + 1][k], a = std::fabs(d);
      m[i * N + k] = d;
      sums[k] += a;
      largest = a > largest ? a : largest;
      lift = k == 0 ? d * d : lift + d * d;
    }
    m[i * N + D] = lift;
    sums[D] += lift;
  }
  return matrix_estimate<N>(m, sums, rounds, largest);
}

}  // namespace sweepcdt::predicates::detail
