// Exact linear feasibility with strict inequalities, for the brute-force CDT oracle (tests only).
//
//   strictly_feasible(strict, weak, n):  is there x in R^n with x >= 0, sum x = 1,
//                                        strict[r] . x > 0 for every r and weak[r] . x >= 0 for every r?
//
// Strictness is decided by a slack: maximise delta subject to strict[r] . x >= delta, 0 <= delta <= 1;
// the system is strictly feasible iff the optimum is > 0. Solved by the two-phase simplex method with
// Bland's rule (which cannot cycle) over GMP rationals: no rounding anywhere. The idea is the one of
// core/src/simplex_intersection_lp.cpp, written again here so the oracle shares no code with the
// library it checks.
#pragma once
#include <gmpxx.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <vector>

namespace sweepcdt::fixtures::lp {

using Q = mpq_class;
using Row = std::vector<Q>;

// A x = b with b >= 0, x >= 0, and a starting basis: basis[i] is a column equal to the unit vector e_i.
class Tableau {
 public:
  Tableau(std::vector<Row> a, Row b, std::vector<std::size_t> basis)
      : t_(std::move(a)), basis_(std::move(basis)), columns_(t_.empty() ? 0 : t_[0].size()) {
    for (std::size_t i = 0; i < t_.size(); ++i) t_[i].push_back(b[i]);
  }

  // Maximises cost . x, only columns < `enterable` may enter the basis. The polytope must be bounded.
  Q maximize(const Row& cost, std::size_t enterable) {
    for (;;) {
      std::optional<std::size_t> entering;
      for (std::size_t j = 0; j < enterable && !entering; ++j)
        if (!basic(j) && sgn(reduced_cost(cost, j)) > 0) entering = j;  // Bland: lowest index
      if (!entering) break;
      std::optional<std::size_t> leaving;
      Q best;
      for (std::size_t i = 0; i < t_.size(); ++i) {
        if (sgn(t_[i][*entering]) <= 0) continue;
        const Q ratio = t_[i][columns_] / t_[i][*entering];
        if (!leaving || ratio < best || (ratio == best && basis_[i] < basis_[*leaving])) leaving = i, best = ratio;
      }
      if (!leaving) throw std::logic_error("rational_lp: unbounded (the caller promised a bounded polytope)");
      pivot(*leaving, *entering);
    }
    Q value = 0;
    for (std::size_t i = 0; i < t_.size(); ++i) value += cost[basis_[i]] * t_[i][columns_];
    return value;
  }

  // Pivots column `column`, if basic at level zero, out of the basis onto a column < `allowed`
  // (a degenerate pivot: no value changes). Left basic when its row is zero there (a redundant row).
  void expel(std::size_t column, std::size_t allowed) {
    for (std::size_t i = 0; i < t_.size(); ++i) {
      if (basis_[i] != column) continue;
      for (std::size_t j = 0; j < allowed; ++j)
        if (!basic(j) && sgn(t_[i][j]) != 0) return pivot(i, j);
    }
  }

 private:
  bool basic(std::size_t j) const {
    for (std::size_t b : basis_)
      if (b == j) return true;
    return false;
  }
  Q reduced_cost(const Row& cost, std::size_t j) const {
    Q r = cost[j];
    for (std::size_t i = 0; i < t_.size(); ++i) r -= cost[basis_[i]] * t_[i][j];
    return r;
  }
  void pivot(std::size_t r, std::size_t c) {
    const Q p = t_[r][c];
    for (Q& x : t_[r]) x /= p;
    for (std::size_t i = 0; i < t_.size(); ++i) {
      if (i == r || sgn(t_[i][c]) == 0) continue;
      const Q f = t_[i][c];
      for (std::size_t j = 0; j <= columns_; ++j) t_[i][j] -= f * t_[r][j];
    }
    basis_[r] = c;
  }

  std::vector<Row> t_;  // rows: coefficients, then the right-hand side
  std::vector<std::size_t> basis_;
  std::size_t columns_;
};

inline bool strictly_feasible(const std::vector<Row>& strict, const std::vector<Row>& weak, std::size_t n) {
  // Columns: x (n) | delta | u (delta + u = 1) | s_r (strict slacks) | w_r (weak slacks) | artificial.
  const std::size_t S = strict.size(), W = weak.size();
  const std::size_t delta = n, u = n + 1, s0 = n + 2, w0 = s0 + S, art = w0 + W, columns = art + 1;
  std::vector<Row> a(2 + S + W, Row(columns));
  Row b(a.size());
  std::vector<std::size_t> basis(a.size());
  // Row 0: sum x + art = 1; its artificial is the only one needed (phase 1 drives it to 0).
  for (std::size_t j = 0; j < n; ++j) a[0][j] = 1;
  a[0][art] = 1, b[0] = 1, basis[0] = art;
  a[1][delta] = 1, a[1][u] = 1, b[1] = 1, basis[1] = u;
  // strict[r] . x - delta - s_r = 0, written with s_r positive so that s_r = 0 starts feasible.
  for (std::size_t r = 0; r < S; ++r) {
    for (std::size_t j = 0; j < n; ++j) a[2 + r][j] = -strict[r][j];
    a[2 + r][delta] = 1, a[2 + r][s0 + r] = 1, basis[2 + r] = s0 + r;
  }
  for (std::size_t r = 0; r < W; ++r) {
    for (std::size_t j = 0; j < n; ++j) a[2 + S + r][j] = -weak[r][j];
    a[2 + S + r][w0 + r] = 1, basis[2 + S + r] = w0 + r;
  }
  Tableau tableau(std::move(a), std::move(b), std::move(basis));
  Row phase1(columns);
  phase1[art] = -1;
  if (sgn(tableau.maximize(phase1, columns)) < 0) return false;  // not even the closed system
  tableau.expel(art, art);
  Row phase2(columns);
  phase2[delta] = 1;
  return sgn(tableau.maximize(phase2, art)) > 0;
}

}  // namespace sweepcdt::fixtures::lp
