// Improper intersection of two (D-1)-simplices by exact linear programming, in any dimension.
//
// A point of a ∩ b is  sum_i lambda_i a_i = sum_j mu_j b_j  with lambda, mu >= 0 summing to 1. Its
// barycentric coordinates in a are unique (a is non-degenerate), and it lies in the shared face iff
// every lambda_i of a non-shared vertex is 0. So the intersection is improper iff
//   max  sum_{i not shared} lambda_i   over that polytope   is > 0.
// Solved by the two-phase simplex method with Bland's rule (no cycling) over GMP rationals.
#include <gmpxx.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "simplex_intersection.h"

namespace sweepcdt::detail {
namespace {

using Row = std::vector<mpq_class>;

class Tableau {
 public:
  // A x = b, x >= 0 with b >= 0; one artificial variable per row starts as the basis.
  Tableau(const std::vector<Row>& a, const Row& b) : rows_(a.size()), structural_(a.empty() ? 0 : a[0].size()) {
    const std::size_t columns = structural_ + rows_;
    t_.assign(rows_, Row(columns + 1));
    basis_.resize(rows_);
    for (std::size_t i = 0; i < rows_; ++i) {
      for (std::size_t j = 0; j < structural_; ++j) t_[i][j] = a[i][j];
      t_[i][structural_ + i] = 1;
      t_[i][columns] = b[i];
      basis_[i] = structural_ + i;
    }
  }

  // Maximises sum_j cost[j] x_j over the columns allowed to enter; returns the optimum.
  mpq_class maximize(const Row& cost, std::size_t enterable_columns) {
    const std::size_t rhs = structural_ + rows_;
    for (;;) {
      std::optional<std::size_t> entering;
      for (std::size_t j = 0; j < enterable_columns && !entering; ++j) {
        if (std::find(basis_.begin(), basis_.end(), j) != basis_.end()) continue;
        mpq_class reduced = cost[j];
        for (std::size_t i = 0; i < rows_; ++i) reduced -= cost[basis_[i]] * t_[i][j];
        if (sgn(reduced) > 0) entering = j;  // Bland: the first improving column
      }
      if (!entering) break;
      std::optional<std::size_t> leaving;
      mpq_class best;
      for (std::size_t i = 0; i < rows_; ++i) {
        if (sgn(t_[i][*entering]) <= 0) continue;
        mpq_class ratio = t_[i][rhs] / t_[i][*entering];
        if (!leaving || ratio < best || (ratio == best && basis_[i] < basis_[*leaving])) {
          leaving = i;
          best = ratio;
        }
      }
      if (!leaving) break;  // unbounded: impossible over a bounded polytope
      pivot(*leaving, *entering);
    }
    mpq_class value = 0;
    for (std::size_t i = 0; i < rows_; ++i) value += cost[basis_[i]] * t_[i][rhs];
    return value;
  }

  // After phase 1: pivots zero-level artificials out of the basis where a structural column allows.
  void expel_artificials() {
    for (std::size_t i = 0; i < rows_; ++i) {
      if (basis_[i] < structural_) continue;
      for (std::size_t j = 0; j < structural_; ++j)
        if (sgn(t_[i][j]) != 0 && std::find(basis_.begin(), basis_.end(), j) == basis_.end()) {
          pivot(i, j);
          break;
        }
    }
  }

  std::size_t structural() const { return structural_; }
  std::size_t rows() const { return rows_; }

 private:
  void pivot(std::size_t r, std::size_t c) {
    const mpq_class p = t_[r][c];
    for (auto& x : t_[r]) x /= p;
    for (std::size_t i = 0; i < rows_; ++i) {
      if (i == r || sgn(t_[i][c]) == 0) continue;
      const mpq_class f = t_[i][c];
      for (std::size_t j = 0; j < t_[i].size(); ++j) t_[i][j] -= f * t_[r][j];
    }
    basis_[r] = c;
  }

  std::size_t rows_, structural_;
  std::vector<Row> t_;
  std::vector<std::size_t> basis_;
};

}  // namespace

template <int D>
bool improper_intersection_lp(const std::array<const double*, D>& a, const std::array<uint32_t, D>& ida,
                              const std::array<const double*, D>& b, const std::array<uint32_t, D>& idb) {
  // Columns: lambda_0..lambda_{D-1}, mu_0..mu_{D-1}. Rows: sum lambda = 1, sum mu = 1, coordinates.
  std::vector<Row> rows(D + 2, Row(2 * D));
  Row rhs(D + 2);
  for (int i = 0; i < D; ++i) {
    rows[0][i] = 1;
    rows[1][D + i] = 1;
    for (int k = 0; k < D; ++k) {
      rows[2 + k][i] = mpq_class(a[i][k]);
      rows[2 + k][D + i] = -mpq_class(b[i][k]);
    }
  }
  rhs[0] = rhs[1] = 1;
  Tableau tableau(rows, rhs);

  Row phase1(2 * D + D + 2);
  for (std::size_t j = 2 * D; j < phase1.size(); ++j) phase1[j] = -1;
  if (sgn(tableau.maximize(phase1, phase1.size())) < 0) return false;  // disjoint
  tableau.expel_artificials();

  Row objective(2 * D + D + 2);
  for (int i = 0; i < D; ++i)
    if (std::find(idb.begin(), idb.end(), ida[i]) == idb.end()) objective[i] = 1;
  return sgn(tableau.maximize(objective, 2 * D)) > 0;
}

template bool improper_intersection_lp<2>(const std::array<const double*, 2>&, const std::array<uint32_t, 2>&,
                                          const std::array<const double*, 2>&, const std::array<uint32_t, 2>&);
template bool improper_intersection_lp<3>(const std::array<const double*, 3>&, const std::array<uint32_t, 3>&,
                                          const std::array<const double*, 3>&, const std::array<uint32_t, 3>&);
template bool improper_intersection_lp<4>(const std::array<const double*, 4>&, const std::array<uint32_t, 4>&,
                                          const std::array<const double*, 4>&, const std::array<uint32_t, 4>&);
template bool improper_intersection_lp<5>(const std::array<const double*, 5>&, const std::array<uint32_t, 5>&,
                                          const std::array<const double*, 5>&, const std::array<uint32_t, 5>&);

}  // namespace sweepcdt::detail
