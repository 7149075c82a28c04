// Paper §3 (priority-queue keys) with the perturbation of §6. Derivations in sweep_keys.h and below.
#include "sweepcdt/predicates/sweep_keys.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "arith.h"
#include "filters4.h"  // and filters3.h
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::predicates {
namespace {

using detail::Dyadic;
using detail::ExactArith;

// Circumcentre of s = (p_0..p_D) relative to p_D solves A c' = b'/2 with rows a_i = p_i - p_D and
// b'_i = |a_i|^2 - eps_i + eps_D (i < D). By Cramer, c_k = p_D[k] + N_k / (2 det A), N_k = det A with
// column k replaced by b'. Hence for two simplices
//   2 det A_s det A_t (c_k(s) - c_k(t)) = 2 (p^s_D[k] - p^t_D[k]) Ds Dt + N_k(s) Dt - N_k(t) Ds.
template <int D, class Arith>
struct Lifted {
  using T = typename Arith::T;
  std::array<T, D * D> a;  // rows p_i - p_D
  std::array<T, D> b;      // |p_i - p_D|^2
  T det;
  Lifted(Arith& arith, const Vertices<D + 1>& s) {
    for (int i = 0; i < D; ++i) {
      for (int k = 0; k < D; ++k) {
        a[i * D + k] = arith.diff(s[i].x[k], s[D].x[k]);
        b[i] = k == 0 ? a[i * D] * a[i * D] : b[i] + a[i * D + k] * a[i * D + k];
      }
    }
    det = detail::determinant<D>(a);
  }
  std::array<T, D * D> with_column(int k, const std::array<T, D>& column) const {
    auto m = a;
    for (int i = 0; i < D; ++i) m[i * D + k] = column[i];
    return m;
  }
};

template <int D>
struct CircumcenterDifference {
  const Vertices<D + 1>& s;
  const Vertices<D + 1>& t;
  int k;
  template <class Arith>
  typename Arith::T operator()(Arith& a) const {
    const Lifted<D, Arith> ls(a, s), lt(a, t);
    const auto nks = detail::determinant<D>(ls.with_column(k, ls.b));
    const auto nkt = detail::determinant<D>(lt.with_column(k, lt.b));
    const auto shift = a.diff(s[D].x[k], t[D].x[k]);
    return (shift + shift) * ls.det * lt.det + nks * lt.det - nkt * ls.det;
  }
};

// Coefficient of eps_v in N_k: the column b' holds -eps_{p_i} in row i and +eps_{p_D} in every row.
template <int D, class Arith>
typename Arith::T eps_coefficient_of_nk(Arith& arith, const Lifted<D, Arith>& l, const Vertices<D + 1>& s, int k,
                                        uint32_t v) {
  using T = typename Arith::T;
  std::array<T, D> column;
  if (s[D].id == v) {
    column.fill(arith.one());
    return detail::determinant<D>(l.with_column(k, column));
  }
  for (int i = 0; i < D; ++i) {
    if (s[i].id != v) continue;
    column.fill(T{});
    column[i] = arith.one();
    return -detail::determinant<D>(l.with_column(k, column));
  }
  return T{};
}

// The coefficient of eps_v in 2 det A_s det A_t (c_k(s) - c_k(t)) (CircumcenterDifference), a formula
// of degree 2D - 1 in the coordinate differences (homogeneous: the constants are the unit columns),
// so it runs through the filter and the fixed-width exact stage like any other.
template <int D>
struct CircumcenterEpsCoefficient {
  const Vertices<D + 1>& s;
  const Vertices<D + 1>& t;
  int k;
  uint32_t v;
  template <class Arith>
  typename Arith::T operator()(Arith& a) const {
    const Lifted<D, Arith> ls(a, s), lt(a, t);
    return eps_coefficient_of_nk<D>(a, ls, s, k, v) * lt.det - eps_coefficient_of_nk<D>(a, lt, t, k, v) * ls.det;
  }
};

template <int D>
std::vector<uint32_t> ids_ascending(const Vertices<D + 1>& s, const Vertices<D + 1>& t) {
  std::vector<uint32_t> ids;
  for (const auto& v : s) ids.push_back(v.id);
  for (const auto& v : t) ids.push_back(v.id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

// A simplex's orientation, from `cache` when it has it (compare_power_sequences).
template <int D>
Sign cached_orientation(const Vertices<D + 1>& s, PowerSequenceCache* cache) {
  if (cache && cache->orientation != 0) return static_cast<Sign>(cache->orientation);
  const Sign o = orient<D>(coords_of(s));
  if (cache) cache->orientation = static_cast<int8_t>(o);
  return o;
}

template <int D>
Sign orientation_product(const Vertices<D + 1>& s, const Vertices<D + 1>& t, const char* who, PowerSequenceCache* s_cache = nullptr,
                         PowerSequenceCache* t_cache = nullptr) {
  const Sign os = cached_orientation<D>(s, s_cache), ot = cached_orientation<D>(t, t_cache);
  if (os == Sign::Zero || ot == Sign::Zero) throw std::invalid_argument(std::string(who) + ": degenerate simplex");
  return os * ot;
}

// The power of q w.r.t. the sphere through the lifted vertices of s is Psi_q(s) = -L_s / Ds, with
// L_s = det [p_i - q, |p_i - q|^2]_{i<=D} (insphere's matrix) and Ds = det [p_i - p_D]. So
//   Ds Dt (Psi_q(s) - Psi_q(t)) = L_t Ds - L_s Dt.
// Perturbed lifts |p_i - q|^2 - eps_{p_i} make L_s(eps) = L_s - sum_i eps_{p_i} K_i, where
// K_i = (-1)^{i+D} det [p_j - q]_{j != i} is the cofactor of the lift in row i. q's own lift cancels.
template <int D, class Arith>
typename Arith::T lifted_det(Arith& arith, const Vertices<D + 1>& s, const Vertex& q) {
  using T = typename Arith::T;
  constexpr int N = D + 1;
  std::array<T, N * N> m;
  for (int i = 0; i <= D; ++i) {
    T lift{};
    for (int k = 0; k < D; ++k) {
      const T d = arith.diff(s[i].x[k], q.x[k]);
      m[i * N + k] = d;
      lift = k == 0 ? d * d : lift + d * d;
    }
    m[i * N + D] = lift;
  }
  return detail::determinant<N>(m);
}

template <int D>
struct PowerDifference {
  const Vertices<D + 1>& s;
  const Vertices<D + 1>& t;
  const Vertex& q;
  template <class Arith>
  typename Arith::T operator()(Arith& a) const {
    const auto ds = detail::orient_det<D>(a, coords_of(s));
    const auto dt = detail::orient_det<D>(a, coords_of(t));
    return lifted_det<D>(a, t, q) * ds - lifted_det<D>(a, s, q) * dt;
  }
};

template <int D, class Arith>
typename Arith::T lift_cofactor(Arith& arith, const Vertices<D + 1>& s, const Vertex& q, uint32_t v) {
  using T = typename Arith::T;
  for (int i = 0; i <= D; ++i) {
    if (s[i].id != v) continue;
    std::array<T, D * D> m;
    for (int j = 0, r = 0; j <= D; ++j) {
      if (j == i) continue;
      for (int k = 0; k < D; ++k) m[r * D + k] = arith.diff(s[j].x[k], q.x[k]);
      ++r;
    }
    const T minor = detail::determinant<D>(m);
    return ((i + D) & 1) ? -minor : minor;
  }
  return T{};
}

// The coefficient of eps_v in L_t Ds - L_s Dt (PowerDifference): homogeneous of degree 2D.
template <int D>
struct PowerEpsCoefficient {
  const Vertices<D + 1>& s;
  const Vertices<D + 1>& t;
  const Vertex& q;
  uint32_t v;
  template <class Arith>
  typename Arith::T operator()(Arith& a) const {
    const auto ds = detail::orient_det<D>(a, coords_of(s));
    const auto dt = detail::orient_det<D>(a, coords_of(t));
    return lift_cofactor<D>(a, s, q, v) * dt - lift_cofactor<D>(a, t, q, v) * ds;
  }
};

// An enclosure of shift + num / den from filtered values: |num - num^| <= e_num, |den - den^| <= e_den gives
// |num/den - q^| <= (e_num + |q^| e_den) / (|den^| - e_den) + the rounding of q^ (see approx.h for
// the filter bound); inflated generously to cover the rounding of this bound itself.
KeyInterval ratio_interval(double num, double e_num, double den, double e_den, double shift = 0.0) {
  const double u = detail::kUnitRoundoff;
  const double q = num / den;
  const double margin = std::fabs(den) - e_den;
  if (!(margin > 0) || !std::isfinite(q) || !std::isfinite(e_num)) return {-INFINITY, INFINITY};
  const double e = ((e_num + std::fabs(q) * e_den) / margin) * (1 + 64 * u) + (std::fabs(q) + std::fabs(shift)) * 8 * u + 0x1p-1000;
  return {shift + q - e, shift + q + e};
}

KeyInterval ratio_interval(const detail::Approx& num, const detail::Approx& den, double shift = 0.0) {
  const auto error = [&](const detail::Approx& a) {
    return (2.0 * a.rounds * detail::kUnitRoundoff) * a.mag + detail::kUnderflowAbsoluteBound;
  };
  return ratio_interval(num.value, error(num), den.value, error(den), shift);
}

}  // namespace

template <int D>
KeyInterval power_interval(const Vertices<D + 1>& s, const double* q) {
  if constexpr (detail::kHandWrittenFilter<D>) {
    // The hand-written filters (filters3.h, filters4.h): L_s is insphere's determinant with q as the
    // last point, Ds orient's. About a tenth of the generic evaluation below, which tracks every
    // operation's magnitude; the sweeps compute one key per new face.
    Coords<D + 2> lifted;
    for (int i = 0; i <= D; ++i) lifted[i] = s[i].x;
    lifted[D + 1] = q;
    const detail::Estimate l = detail::insphere_estimate<D>(lifted), d = detail::orient_estimate<D>(coords_of(s));
    return ratio_interval(-l.value, l.error, d.value, d.error);
  }
  detail::FilterArith a;
  // Psi_q(s) = -L_s / Ds.
  const auto l = lifted_det<D>(a, s, Vertex{q, 0});
  const auto d = detail::orient_det<D>(a, coords_of(s));
  return ratio_interval(-l, d);
}

template <int D>
PowerWords power_words(const Vertices<D + 1>& s, const double* q) {
  detail::DDFilterArith a;
  const detail::DDApprox l = lifted_det<D>(a, s, Vertex{q, 0}), d = detail::orient_det<D>(a, coords_of(s));
  return {l.hi, l.lo, l.mag, l.rounds, d.hi, d.lo, d.mag, d.rounds};
}

std::optional<Sign> power_order_from_words(const PowerWords& s, const PowerWords& t) {
  const detail::DDApprox ls{s.l_hi, s.l_lo, s.l_mag, s.l_rounds}, ds{s.d_hi, s.d_lo, s.d_mag, s.d_rounds};
  const detail::DDApprox lt{t.l_hi, t.l_lo, t.l_mag, t.l_rounds}, dt{t.d_hi, t.d_lo, t.d_mag, t.d_rounds};
  // PowerDifference's formula: sign(Psi_q(s) - Psi_q(t)) = sign(L_t Ds - L_s Dt) sign(Ds Dt).
  const std::optional<Sign> sign_s = detail::certain_sign(ds), sign_t = detail::certain_sign(dt);
  if (!sign_s || !sign_t) return std::nullopt;
  const std::optional<Sign> r = detail::certain_sign(lt * ds - ls * dt);
  if (!r) return std::nullopt;
  return *r * *sign_s * *sign_t;
}

template <int D>
KeyInterval circumcenter_interval(const Vertices<D + 1>& s, int k) {
  detail::FilterArith a;
  // c_k = p_D[k] + N_k / (2 det A).
  const Lifted<D, detail::FilterArith> l(a, s);
  const auto nk = detail::determinant<D>(l.with_column(k, l.b));
  return ratio_interval(nk, l.det + l.det, s[D].x[k]);
}

// Is a vertex of t (the first one not in s) on the circumsphere of s? Then the keys of s and t tie
// because D+2 points are cospherical, a tie another perturbation order could decide otherwise
// (count_tie, stats.h). Keys also tie without it — centres on a common axis-parallel line, a delta
// vertex on the radical plane of two spheres, both common in CAD meshes —, and the perturbation
// orders those too, but no order changes which simplices are constrained Delaunay there. One exact
// insphere, on ties only.
template <int D>
bool cospherical_tie(const Vertices<D + 1>& s, const Vertices<D + 1>& t) {
  for (const Vertex& v : t) {
    if (std::any_of(s.begin(), s.end(), [&](const Vertex& w) { return w.x == v.x; })) continue;
    Coords<D + 2> p;
    for (int i = 0; i <= D; ++i) p[i] = s[i].x;
    p[D + 1] = v.x;
    return insphere<D>(p) == Sign::Zero;
  }
  return false;
}

template <int D>
Sign compare_circumcenters(const Vertices<D + 1>& s, const Vertices<D + 1>& t) {
  const Sign sigma = orientation_product<D>(s, t, "compare_circumcenters");
  bool tie_checked = false;  // one cospherical tie per comparison
  for (int k = 0; k < D; ++k) {
    const Sign r = detail::filtered_sign(CircumcenterDifference<D>{s, t, k});
    if (r != Sign::Zero) return r * sigma;
    // Equal unperturbed coordinate: the eps terms decide, least vertex id first.
    detail::count_perturbed();
    if (!tie_checked && cospherical_tie<D>(s, t)) detail::count_tie();
    tie_checked = true;
    for (const uint32_t v : ids_ascending<D>(s, t)) {
      const Sign c = detail::filtered_sign(CircumcenterEpsCoefficient<D>{s, t, k, v});
      if (c != Sign::Zero) return c * sigma;
    }
  }
  return Sign::Zero;
}

// sign(Psi_q(s) - Psi_q(t)) * sign(Ds Dt) before the perturbation.
template <int D>
Sign power_difference(const Vertices<D + 1>& s, const Vertices<D + 1>& t, const Vertex& q) {
  return detail::filtered_sign(PowerDifference<D>{s, t, q});
}

// The same from the eps terms, least vertex id first: decides a tie of power_difference().
template <int D>
Sign power_difference_perturbed(const Vertices<D + 1>& s, const Vertices<D + 1>& t, const Vertex& q) {
  detail::count_perturbed();
  for (const uint32_t v : ids_ascending<D>(s, t)) {
    const Sign c = detail::filtered_sign(PowerEpsCoefficient<D>{s, t, q, v});
    if (c != Sign::Zero) return c;
  }
  return Sign::Zero;
}

template <int D>
Sign compare_power(const Vertices<D + 1>& s, const Vertices<D + 1>& t, const Vertex& q) {
  const Sign sigma = orientation_product<D>(s, t, "compare_power");
  const Sign r = power_difference<D>(s, t, q);
  return (r != Sign::Zero ? r : power_difference_perturbed<D>(s, t, q)) * sigma;
}

// s and t share a facet f (t's vertices but its apex b). Then Psi_x(s) - Psi_x(t) is an affine
// function of x that vanishes on aff(f), perturbation included (both perturbed spheres pass through
// f's lifted points): lambda * orient(f, x). At b it is the perturbed height of b's lifted point over
// s's lifted hyperplane, negative iff b is inside s's perturbed circumsphere. So the tuple's first
// non-zero entry belongs to the first delta vertex off aff(f), and its sign needs one perturbed
// insphere and a few orientations — instead of exact zeros, term by term, whenever a delta vertex
// lies on aff(f) (the star sweep's centre on a facet through it, seeds on CAD planes).
template <int D>
Sign compare_power_tuples_across(const Vertices<D + 1>& s, const Vertices<D + 1>& t, int apex, const Vertex* delta, const int8_t* toward, int n) {
  const auto side = [&](const double* x) {
    Coords<D + 1> c;
    for (int j = 0, k = 0; j <= D; ++j)
      if (j != apex) c[k++] = t[j].x;
    c[D] = x;
    return orient<D>(c);
  };
  // The perturbed insphere counts a cospherical tie when it meets one (the general path counts it
  // too). Comparing the enclosures first, as the callers do at Delta_0, cost more than the exact
  // formula: two power enclosures against one filtered insphere and two orientations (star sweeps of
  // Steiner points on flat facets, whose centre lies on aff(f) for every facet of a sheet).
  for (int k = 0; k < n; ++k) {
    const Sign o = side(delta[k].x);
    if (o == Sign::Zero) continue;
    const Sign r = (inside_circumsphere<D>(s, t[apex]) ? Sign::Negative : Sign::Positive) * side(t[apex].x) * o;
    return toward[k] > 0 ? r : -r;
  }
  return Sign::Zero;
}

template <int D>
Sign compare_power_tuples(const Vertices<D + 1>& s, const Vertices<D + 1>& t, const Vertices<D + 1>& delta) {
  std::array<int8_t, D + 1> toward;
  toward.fill(1);
  return compare_power_sequences<D>(s, t, delta.data(), toward.data(), D + 1);
}

// A simplex's power enclosure at q_k (k >= 1), from `cache` when it has it.
// Two enclosures apart decide sign(Psi_q(s) - Psi_q(t)): then the unperturbed powers differ and the
// perturbation cannot change the order. Past an exact tie at Delta_0 the next entries mostly differ
// clearly: the star sweep's centre on the segment it merges is on the line of every simplex's edge
// ab there, so all their powers at it are |pa| |pb| (41% of the star sweeps' exact comparisons on
// pipe_tee_std; most others share a facet), and two enclosures decide the next entry instead of the
// generic filter and often its exact stage (PowerDifference: about 7000 instructions a comparison).
template <int D>
KeyInterval cached_power_interval(const Vertices<D + 1>& s, const Vertex* delta, int k, PowerSequenceCache* cache) {
  if (!cache) return power_interval<D>(s, delta[k].x);
  if (!(cache->known >> k & 1)) cache->at[k] = power_interval<D>(s, delta[k].x), cache->known |= static_cast<uint8_t>(1u << k);
  return cache->at[k];
}

template <int D>
Sign compare_power_sequences(const Vertices<D + 1>& s, const Vertices<D + 1>& t, const Vertex* delta, const int8_t* toward, int n,
                             PowerSequenceCache* s_cache, PowerSequenceCache* t_cache) {
  int apex = -1, others = 0;  // t's vertices not in s
  for (int j = 0; j <= D; ++j)
    if (std::none_of(s.begin(), s.end(), [&](const Vertex& w) { return w.id == t[j].id; })) apex = j, ++others;
  if (others == 1) return compare_power_tuples_across<D>(s, t, apex, delta, toward, n);
  // Sharing an edge ab, the difference (perturbation included) vanishes at a and b, so on their
  // line: a delta vertex there gives an exact zero, known without the exact stages (the star
  // sweep's centre on a segment through a deleted Steiner point, common).
  const Vertex* edge[2];
  int shared = 0;
  for (const Vertex& v : t)
    if (std::any_of(s.begin(), s.end(), [&](const Vertex& w) { return w.id == v.id; }) && shared < 2) edge[shared++] = &v;
  const bool on_edge_line_possible = D - others + 1 == 2;
  const Sign sigma = orientation_product<D>(s, t, "compare_power_tuples", s_cache, t_cache);
  const auto vertex_of = [](const Vertices<D + 1>& u, uint32_t id) {
    return std::any_of(u.begin(), u.end(), [&](const Vertex& w) { return w.id == id; });
  };
  for (int i = 0; i < n; ++i) {
    // Past Delta_0, whose enclosures the callers compared already, first the enclosures: apart, they
    // also rule out the exact zeros below.
    if (i > 0) {
      const KeyInterval a = cached_power_interval<D>(s, delta, i, s_cache), b = cached_power_interval<D>(t, delta, i, t_cache);
      if (a.hi < b.lo) return toward[i] > 0 ? Sign::Negative : Sign::Positive;
      if (b.hi < a.lo) return toward[i] > 0 ? Sign::Positive : Sign::Negative;
    }
    // A delta vertex of both simplices has power 0 for both, perturbation included (its lifted point
    // is on both lifted spheres): an exact zero known from the ids, which the exact stages would
    // otherwise find term by term (every comparison of two simplices through the sphere's seed
    // vertex: in D = 5 most of the exact work).
    const bool vertex_of_both = vertex_of(s, delta[i].id) && vertex_of(t, delta[i].id);
    if (vertex_of_both || (on_edge_line_possible && collinear<D>(edge[0]->x, edge[1]->x, delta[i].x))) {
      if (i == 0 && cospherical_tie<D>(s, t)) detail::count_tie();
      continue;
    }
    Sign r = power_difference<D>(s, t, delta[i]);
    if (r == Sign::Zero) {
      if (i == 0 && cospherical_tie<D>(s, t)) detail::count_tie();
      r = power_difference_perturbed<D>(s, t, delta[i]);
    }
    if (r != Sign::Zero) return toward[i] > 0 ? r * sigma : -(r * sigma);
  }
  return Sign::Zero;
}

#define SWEEPCDT_INSTANTIATE(D)                                                                  \
  template KeyInterval power_interval<D>(const Vertices<D + 1>&, const double*);                  \
  template PowerWords power_words<D>(const Vertices<D + 1>&, const double*);                       \
  template KeyInterval circumcenter_interval<D>(const Vertices<D + 1>&, int);                     \
  template Sign compare_circumcenters<D>(const Vertices<D + 1>&, const Vertices<D + 1>&);        \
  template Sign compare_power<D>(const Vertices<D + 1>&, const Vertices<D + 1>&, const Vertex&); \
  template Sign compare_power_tuples<D>(const Vertices<D + 1>&, const Vertices<D + 1>&, const Vertices<D + 1>&); \
  template Sign compare_power_sequences<D>(const Vertices<D + 1>&, const Vertices<D + 1>&, const Vertex*, const int8_t*, int, \
                                          PowerSequenceCache*, PowerSequenceCache*);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::predicates
