// A brute-force reference for the CDT of a small PLC whose domain is its convex hull (no exterior
// notations), D = 2..5: every (D+1)-subset of the vertices is tested against the definition of paper
// §1 directly, with exact rational arithmetic. A D-simplex s is constrained Delaunay iff
//   (1) no constraining (D-1)-simplex meets int(s), and
//   (2) no vertex inside its circumsphere (perturbed, paper §6: predicates::inside_circumsphere) is
//       visible from any point of int(s).
// Under the perturbation the constrained Delaunay simplices are the CDT when one exists.
//
// Why (2) needs more than a test from one point: a vertex may be hidden from int(s) by the union of
// several constraints, none of which hides it alone. So the set of points of int(s) that t hides from
// v is made explicit. v and p are occluded by t (§1) iff they lie strictly on opposite sides of aff(t)
// and segment pv meets t. With p - v = sum_j c_j (t_j - v) (the t_j - v are a basis when v is off
// aff(t)), pv meets the closed t iff every c_j >= 0, and p is strictly beyond aff(t) iff sum c_j > 1:
//   O_t = int(s) ∩ {beyond_t > 0} ∩ {cone_t,k >= 0 for k < D},
// beyond_t the affine function of aff(t) positive on the side away from v, cone_t,k the one of the
// hyperplane through v and t without t_k, positive at t_k (it is c_k times a positive constant).
// v is visible from int(s) iff int(s) minus the union of the O_t is non-empty, and int(s) \ O_t is
// {beyond_t <= 0} ∪ {cone_t,0 < 0} ∪ ... ∪ {cone_t,D-1 < 0}: a disjunction of linear systems with
// strict and non-strict inequalities, searched depth first, each decided by rational_lp.h.
// Points of int(s) are written p = sum_i beta_i s_i with beta > 0, sum beta = 1, so an affine
// function f becomes the row (f(s_0), ..., f(s_D)) over beta: every coefficient is exact in mpq.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

#include "rational_affine.h"
#include "rational_lp.h"
#include "rational_reference.h"
#include "sweepcdt/plc.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::fixtures {

// What the oracle saw, so that tests can show that each of its branches was taken.
struct BruteForceCdtCounts {
  uint64_t candidates = 0;            // non-degenerate (D+1)-subsets
  uint64_t crossed = 0;               // rejected by (1): a constraint meets the interior
  uint64_t visible = 0;               // rejected by (2): a vertex inside the circumsphere is visible
  uint64_t accepted_by_occlusion = 0; // accepted although a vertex lies inside the circumsphere
  uint64_t hidden = 0;                // (simplex, vertex inside) pairs found hidden ...
  uint64_t hidden_by_union = 0;       // ... of which no single constraint hides the vertex
  uint64_t linear_programs = 0;
};

enum class Sight { Visible, HiddenBySingle, HiddenByUnion };

template <int D>
class CdtOracle {
 public:
  using Ids = std::array<uint32_t, D + 1>;

  explicit CdtOracle(const Plc<D>& plc) : plc_(plc) {
    if (!plc.exterior.empty()) throw std::invalid_argument("CdtOracle: convex-hull domains only");
    for (uint32_t i = 0; i < plc.num_points(); ++i) q_.push_back(ref::point(plc.point(i), D));
    shadows_.resize(plc.num_points() * plc.num_simplices());
    sides_.resize(plc.num_points() * plc.num_simplices());
    for (uint32_t v = 0; v < plc.num_points(); ++v)
      for (std::size_t t = 0; t < plc.num_simplices(); ++t) {
        shadows_[v * plc.num_simplices() + t] = shadow(v, t);
        predicates::Coords<D + 1> c;
        for (int j = 0; j < D; ++j) c[j] = plc.point(plc.simplex(t)[j]);
        c[D] = plc.point(v);
        sides_[v * plc.num_simplices() + t] = predicates::orient<D>(c);
      }
  }

  // Condition (1): does constraint t meet the interior of s (non-degenerate)?
  bool meets_interior(const Ids& s, std::size_t t) const {
    return may_meet_interior(s, t) && meets_interior_exactly(s, t);
  }

  // Condition (2) for one vertex v (not a vertex of s): is v visible from some point of int(s)?
  Sight sight(const Ids& s, uint32_t v) const {
    std::vector<Shadow> candidates;  // the O_t that may meet int(s), as rows over beta
    for (std::size_t t = 0; t < plc_.num_simplices(); ++t) {
      const auto& shadow = shadows_[v * plc_.num_simplices() + t];
      if (!shadow) continue;  // v in aff(t): t occludes nothing from v
      Shadow rows{values(shadow->beyond, s), {}};
      for (int k = 0; k < D; ++k) rows.cone[k] = values(shadow->cone[k], s);
      if (!any_positive(rows.beyond)) continue;  // int(s) is on v's closed side of aff(t)
      const auto misses = [](const lp::Row& r) { return !any_positive(r); };
      if (std::any_of(rows.cone.begin(), rows.cone.end(), misses))
        continue;  // int(s) is strictly outside the cone from v through t (s is non-degenerate)
      candidates.push_back(rows);
    }
    // Fast exact exit: the centroid (the row sums, up to a positive factor) is hidden by none.
    const auto hides_centroid = [](const Shadow& r) {
      const auto inside = [](const lp::Row& c) { return sgn(sum(c)) >= 0; };
      return sgn(sum(r.beyond)) > 0 && std::all_of(r.cone.begin(), r.cone.end(), inside);
    };
    const bool centroid_hidden = std::any_of(candidates.begin(), candidates.end(), hides_centroid);
    if (!centroid_hidden) return Sight::Visible;
    std::vector<Shadow> relevant;  // those whose O_t does meet int(s): the others cannot matter
    for (const Shadow& rows : candidates) {
      std::vector<lp::Row> weak(rows.cone.begin(), rows.cone.end());
      if (feasible(with(interior_rows(), rows.beyond), weak)) relevant.push_back(rows);
    }
    std::vector<lp::Row> strict = interior_rows(), weak;
    if (escapes(relevant, 0, strict, weak)) return Sight::Visible;
    // Hidden. By one constraint alone iff int(s) \ O_t is empty for that t.
    for (const Shadow& r : relevant) {
      std::vector<Shadow> one{r};
      std::vector<lp::Row> strict1 = interior_rows(), weak1;
      if (!escapes(one, 0, strict1, weak1)) return Sight::HiddenBySingle;
    }
    return Sight::HiddenByUnion;
  }

  // Both conditions; counts what decided. The linear programs of (1) run last: most simplices fail
  // (2) at a vertex seen from the centroid, which costs no linear program.
  bool constrained_delaunay(const Ids& s) const {
    std::vector<std::size_t> undecided;
    for (std::size_t t = 0; t < plc_.num_simplices(); ++t)
      if (may_meet_interior(s, t)) undecided.push_back(t);
    predicates::Vertices<D + 1> sv;
    for (int i = 0; i <= D; ++i) sv[i] = {plc_.point(s[i]), s[i]};
    uint64_t hidden = 0, hidden_by_union = 0;
    for (uint32_t v = 0; v < plc_.num_points(); ++v) {
      if (std::find(s.begin(), s.end(), v) != s.end()) continue;
      if (!predicates::inside_circumsphere<D>(sv, {plc_.point(v), v})) continue;
      const Sight sight_of_v = sight(s, v);
      if (sight_of_v == Sight::Visible) return ++counts.visible, false;
      ++hidden;
      hidden_by_union += sight_of_v == Sight::HiddenByUnion;
    }
    for (std::size_t t : undecided)
      if (meets_interior_exactly(s, t)) return ++counts.crossed, false;
    counts.hidden += hidden;
    counts.hidden_by_union += hidden_by_union;
    counts.accepted_by_occlusion += hidden > 0;
    return true;
  }

  mutable BruteForceCdtCounts counts;

 private:
  struct Shadow {  // O_t as rows over beta: beyond > 0 and every cone[k] >= 0
    lp::Row beyond;
    std::array<lp::Row, D> cone;
  };
  struct ShadowFunctions {
    Affine beyond;
    std::array<Affine, D> cone;
  };

  // Condition (1) by exact predicates only: false when t surely misses int(s) (s on one closed side
  // of aff(t), or t on the closed outer side of a facet hyperplane of s), else true (undecided).
  bool may_meet_interior(const Ids& s, std::size_t t) const {
    bool positive = false, negative = false;
    for (uint32_t i : s) {
      positive |= sides_[i * plc_.num_simplices() + t] == predicates::Sign::Positive;
      negative |= sides_[i * plc_.num_simplices() + t] == predicates::Sign::Negative;
    }
    if (!positive || !negative) return false;
    const uint32_t* f = plc_.simplex(t);
    const auto o = predicates::orient<D>(coords(s));
    for (int i = 0; i <= D; ++i) {
      bool outside = true;
      for (int j = 0; j < D && outside; ++j) {
        auto c = coords(s);
        c[i] = plc_.point(f[j]);
        outside = predicates::to_int(predicates::orient<D>(c) * o) <= 0;
      }
      if (outside) return false;
    }
    return true;
  }

  // Condition (1) exactly: is there lambda >= 0, sum lambda = 1, with every barycentric coordinate
  // (in s) of sum_j lambda_j t_j positive? Row i holds coordinate i of each t_j.
  bool meets_interior_exactly(const Ids& s, std::size_t t) const {
    const uint32_t* f = plc_.simplex(t);
    std::vector<ref::Vec> sq, tq;
    for (uint32_t i : s) sq.push_back(q_[i]);
    for (int j = 0; j < D; ++j) tq.push_back(q_[f[j]]);
    const auto b = barycentric(sq, tq);
    std::vector<lp::Row> strict(D + 1, lp::Row(D));
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j < D; ++j) strict[i][j] = b[j][i];
    // The centroid of t inside s (every row sum positive) settles it without the LP.
    if (std::all_of(strict.begin(), strict.end(), [](const lp::Row& r) { return sgn(sum(r)) > 0; })) return true;
    ++counts.linear_programs;
    return lp::strictly_feasible(strict, {}, D);
  }

  // O_t for vertex v and constraint t as affine functions; nullopt when v lies in aff(t).
  std::optional<ShadowFunctions> shadow(uint32_t v, std::size_t t) const {
    const uint32_t* f = plc_.simplex(t);
    std::vector<ref::Vec> tq;
    for (int j = 0; j < D; ++j) tq.push_back(q_[f[j]]);
    const auto towards_v = positive_at(hyperplane_through(tq), q_[v]);
    if (!towards_v) return std::nullopt;
    ShadowFunctions s{towards_v->negated(), {}};  // positive away from v
    for (int k = 0; k < D; ++k) {
      std::vector<ref::Vec> points{q_[v]};
      for (int j = 0; j < D; ++j)
        if (j != k) points.push_back(tq[j]);
      s.cone[k] = hyperplane_through(points, tq[k]);  // t_k is off it because v is off aff(t)
    }
    return s;
  }

  // Depth first over the disjunction: is there a point of int(s) outside O_t for every t in
  // relevant[level..], within the system (strict, weak) already chosen (which is feasible)?
  bool escapes(const std::vector<Shadow>& relevant, std::size_t level, std::vector<lp::Row>& strict,
               std::vector<lp::Row>& weak) const {
    if (level == relevant.size()) return true;
    const Shadow& r = relevant[level];
    weak.push_back(negated(r.beyond));  // on v's closed side of aff(t)
    if (feasible(strict, weak) && escapes(relevant, level + 1, strict, weak)) return true;
    weak.pop_back();
    for (int k = 0; k < D; ++k) {  // strictly outside the cone's facet k
      strict.push_back(negated(r.cone[k]));
      if (feasible(strict, weak) && escapes(relevant, level + 1, strict, weak)) return true;
      strict.pop_back();
    }
    return false;
  }

  bool feasible(const std::vector<lp::Row>& strict, const std::vector<lp::Row>& weak) const {
    ++counts.linear_programs;
    return lp::strictly_feasible(strict, weak, D + 1);
  }

  static std::vector<lp::Row> interior_rows() {  // beta_i > 0
    std::vector<lp::Row> rows(D + 1, lp::Row(D + 1));
    for (int i = 0; i <= D; ++i) rows[i][i] = 1;
    return rows;
  }
  static std::vector<lp::Row> with(std::vector<lp::Row> rows, const lp::Row& row) {
    rows.push_back(row);
    return rows;
  }
  lp::Row values(const Affine& f, const Ids& s) const {
    lp::Row row(D + 1);
    for (int i = 0; i <= D; ++i) row[i] = f.at(q_[s[i]]);
    return row;
  }
  static lp::Row negated(lp::Row row) {
    for (auto& x : row) x = -x;
    return row;
  }
  static lp::Q sum(const lp::Row& row) {
    lp::Q total = 0;
    for (const auto& x : row) total += x;
    return total;
  }
  static bool any_positive(const lp::Row& row) {
    return std::any_of(row.begin(), row.end(), [](const lp::Q& x) { return sgn(x) > 0; });
  }
  predicates::Coords<D + 1> coords(const Ids& s) const {
    predicates::Coords<D + 1> c;
    for (int i = 0; i <= D; ++i) c[i] = plc_.point(s[i]);
    return c;
  }

  const Plc<D>& plc_;
  std::vector<ref::Vec> q_;
  std::vector<std::optional<ShadowFunctions>> shadows_;  // [v * m + t]
  std::vector<predicates::Sign> sides_;                   // [v * m + t]: side of aff(t) v lies on
};

template <int D>
struct BruteForceCdt {
  std::set<std::vector<uint32_t>> simplices;  // sorted vertex ids
  BruteForceCdtCounts counts;
};

// All constrained Delaunay D-simplices of `plc` (convex-hull domain). O(n^{D+2} m) predicates plus
// linear programs only where a constraint may matter: for a handful of points only.
template <int D>
BruteForceCdt<D> brute_force_cdt(const Plc<D>& plc) {
  CdtOracle<D> oracle(plc);
  BruteForceCdt<D> result;
  const uint32_t n = static_cast<uint32_t>(plc.num_points());
  if (n < D + 1) return result;
  std::vector<bool> mask(n, false);
  std::fill(mask.begin(), mask.begin() + D + 1, true);
  do {
    typename CdtOracle<D>::Ids s;
    for (uint32_t i = 0, k = 0; i < n; ++i)
      if (mask[i]) s[k++] = i;
    predicates::Coords<D + 1> c;
    for (int i = 0; i <= D; ++i) c[i] = plc.point(s[i]);
    if (predicates::orient<D>(c) == predicates::Sign::Zero) continue;
    ++oracle.counts.candidates;
    if (oracle.constrained_delaunay(s)) result.simplices.insert(std::vector<uint32_t>(s.begin(), s.end()));
  } while (std::prev_permutation(mask.begin(), mask.end()));
  result.counts = oracle.counts;
  return result;
}

}  // namespace sweepcdt::fixtures
