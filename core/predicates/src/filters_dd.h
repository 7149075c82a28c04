// A semi-static floating-point filter for orient and insphere in D >= 5, where no hand-written one
// exists (filters3.h, filters4.h): the determinant in doubles by the generic expansion (arith.h's
// determinant<N>, as a flat table of steps), and a bound computed from the matrix's column sums instead of
// carried through every operation as the generic filter (approx.h) does.
//
// Why the bound holds: approx.h bounds the error by gamma_k M, where k is the expansion's rounding
// depth and M the same expansion over absolute values: the permanent of |A| for the exact entries A.
// The permanent is at most the product of the column sums of |A| (expanding that product gives every
// permutation's term, and more). The computed entries and sums differ from the exact ones by factors
// (1 + gamma_j), j <= 2D + 2 (at most 12 roundings per entry and sum, 6 for the product), which the
// factor 1 + 2^-40 covers many times over (column_sums_bound, filters3.h); and gamma_k <= 1.25 k u
// < 2 k u. k depends on the expansion's shape only, so it is found once by running the expansion on
// Approx values.
// The column sums overestimate M by up to N^N / N! (65x for a 6x6 matrix of like entries): a filter
// that fails more often near degeneracy, which only costs the generic filter and the exact stage.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

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

// The steps of determinant<N>'s expansion as a flat table: for each row subset of two or more rows
// (by size), its k x k minor over the first k columns is the signed sum, over its rows r, of entry
// (r, k - 1) times the minor of the subset without r, in determinant<N>'s order of rows and of
// operations (so its rounding depth is the same). Evaluating the table needs no bit tests or branches.
struct ExpansionStep {
  uint8_t entry;    // r N + k - 1
  uint8_t minor;    // the subset without r
  uint8_t target;   // the subset
  uint8_t kind;     // 0: the first term, + ; 1: the first term, - ; 2: add ; 3: subtract
};
template <int N>
constexpr std::array<ExpansionStep, N * (1u << (N - 1)) - N> expansion_steps() {
  std::array<ExpansionStep, N * (1u << (N - 1)) - N> steps{};
  constexpr auto subsets = subsets_by_size<N>();
  std::size_t next = 0;
  for (std::size_t m = N; m < subsets.size(); ++m) {
    const unsigned mask = subsets[m].mask;
    const int k = subsets[m].size;
    int position = 0;
    for (int r = 0; r < N; ++r) {
      if (!((mask >> r) & 1u)) continue;
      const bool negative = ((position + k - 1) & 1) != 0;
      const uint8_t kind = position == 0 ? (negative ? 1 : 0) : (negative ? 3 : 2);
      steps[next++] = {static_cast<uint8_t>(r * N + k - 1), static_cast<uint8_t>(mask & ~(1u << r)),
                       static_cast<uint8_t>(mask), kind};
      ++position;
    }
  }
  return steps;
}

// determinant<N>(m) for doubles, the same operations in the same order (equal results), unrolled at
// compile time: every step's indices and sign are constants.
template <int N>
double table_determinant(const std::array<double, N * N>& a) {
  static constexpr auto steps = expansion_steps<N>();
  std::array<double, (1u << N)> minor;
  for (int r = 0; r < N; ++r) minor[1u << r] = a[r * N];
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    const auto step = [&]<std::size_t J>(std::integral_constant<std::size_t, J>) {
      constexpr ExpansionStep s = steps[J];
      const double term = a[s.entry] * minor[s.minor];
      if constexpr (s.kind == 0) minor[s.target] = term;
      else if constexpr (s.kind == 1) minor[s.target] = -term;
      else if constexpr (s.kind == 2) minor[s.target] += term;
      else minor[s.target] -= term;
    };
    (step(std::integral_constant<std::size_t, I>{}), ...);
  }(std::make_index_sequence<steps.size()>{});
  return minor[(1u << N) - 1];
}

template <int N>
Estimate matrix_estimate(const std::array<double, N * N>& m, const std::array<double, N>& column_sums, int rounds,
                         double largest_difference) {
  return {table_determinant<N>(m), column_sums_bound(rounds, column_sums, largest_difference)};
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
