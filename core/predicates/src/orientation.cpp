// orient and insphere for D = 1..5: generic formulas through filtered_sign(), and hand-written 3D
// and 4D filters (filters3.h, filters4.h: the hot paths of the sweeps) with bounds derived as in
// approx.h; in D = 5 a semi-static filter first (filters_dd.h).
#include "sweepcdt/predicates/orientation.h"

#include <algorithm>
#include <cmath>

#include "arith.h"
#include "filters4.h"  // and filters3.h
#include "filters_dd.h"
#include "orient_small.h"

namespace sweepcdt::predicates {
namespace {

using detail::ExactArith;

template <int D>
struct OrientFormula {
  const Coords<D + 1>& p;
  template <class Arith>
  typename Arith::T operator()(Arith& a) const {
    return detail::orient_det<D>(a, p);
  }
};

template <int D>
struct InsphereFormula {
  const Coords<D + 2>& p;
  template <class Arith>
  typename Arith::T operator()(Arith& a) const {
    using T = typename Arith::T;
    constexpr int N = D + 1;
    std::array<T, N * N> m;
    for (int i = 0; i <= D; ++i) {
      T lift{};
      for (int k = 0; k < D; ++k) {
        const T d = a.diff(p[i][k], p[D + 1][k]);
        m[i * N + k] = d;
        lift = k == 0 ? d * d : lift + d * d;
      }
      m[i * N + D] = lift;
    }
    return detail::determinant<N>(m);
  }
};

// The hand-written 3D and 4D filters are in filters3.h and filters4.h.
using detail::largest_magnitude;

// Exact-zero fast path, tried only after the filter failed: a determinant with two equal points
// among its arguments is exactly zero (orient: two equal rows p_i - p_n, or a zero row; insphere: the
// same rows with equal lifts). A purely combinatorial test on the coordinates (== on doubles is exact),
// so no tolerance; it spares the exact stage the commonest exact zero of the sweeps — a face tested
// against one of its own vertices (the sweep sphere's seed vertices are input vertices).
// Non-finite input is left to the exact stage, which reports it.
template <std::size_t N>
inline bool has_equal_points(const std::array<const double*, N>& p, int dim) {
  for (std::size_t i = 0; i < N; ++i)
    for (int k = 0; k < dim; ++k)
      if (!std::isfinite(p[i][k])) return false;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) {
      bool equal = true;
      for (int k = 0; k < dim && equal; ++k) equal = p[i][k] == p[j][k];
      if (equal) return true;
    }
  return false;
}

// An exact-zero fast path of orient (2D, 3D): all points with one coordinate exactly equal lie in
// an axis-parallel hyperplane, so the difference column of that axis is zero and so is the
// determinant. The commonest exact zero of flat CAD faces — the self-intersection check's coplanar
// triangle pairs on faces with z = const, and the 2D tests in their projections — which the
// fixed-width exact stage otherwise computes in full (its dry run alone was 14% of flange_fine.stl).
template <std::size_t N>
inline bool share_a_coordinate(const std::array<const double*, N>& p, int dim) {
  for (std::size_t i = 0; i < N; ++i)
    for (int k = 0; k < dim; ++k)
      if (!std::isfinite(p[i][k])) return false;
  for (int k = 0; k < dim; ++k) {
    bool equal = true;
    for (std::size_t i = 1; i < N && equal; ++i) equal = p[i][k] == p[0][k];
    if (equal) return true;
  }
  return false;
}

// The second exact-zero fast path of orient3: three of the four points on one line (then the four
// are coplanar). Steiner points split segments at parameters of few bits (steiner_point.h), so on
// float-coordinate surfaces most lie exactly on their segments, and the star sweeps of their
// deletion ask orient3 of such triples with a fourth point all the time: 46-64% of the exact calls
// on CAD parts. The test is exact: the differences b - a and c - a must come out exact (Knuth's
// TwoDiff error is zero), and then each component of their cross product is zero iff its two
// products are equal exactly — compared as fl(x*y) and the exact remainder fma(x, y, -fl(x*y)),
// which represent a product uniquely while nothing overflows or underflows: every nonzero factor of
// products found equal must lie in [2^-400, 2^400]. Anything else answers "not known", and the exact
// stage decides.
inline bool exact_difference(double a, double b, double& d) {
  d = a - b;
  const double b_virtual = a - d, a_virtual = d + b_virtual;
  return (b_virtual - b) + (a - a_virtual) == 0;  // TwoDiff's error, exact
}
inline bool safe_factor(double x) {
  const double m = std::fabs(x);
  return x == 0 || (m >= 0x1p-400 && m <= 0x1p400);
}
// x y == u w, exactly. Only a "yes" needs the range check (under- or overflow can make different
// products look alike), so most calls, which say no, skip it.
inline bool products_equal(double x, double y, double u, double w) {
  const double p = x * y, q = u * w;
  if (p != q || std::fma(x, y, -p) != std::fma(u, w, -q)) return false;
  return safe_factor(x) && safe_factor(y) && safe_factor(u) && safe_factor(w);
}
// Whether u x w is clearly not zero in floating point: a component whose rounded value exceeds the
// error it could have if it were zero — the rounded products put at most about 3 units of roundoff
// of each product into it (8 allowed), an absolute term stays far above underflow, NaN says
// nothing. A "clearly" that rounded differences got wrong only skips the fast path, never a sign.
inline bool cross_clearly_nonzero(const double* u, const double* w) {
  const auto component = [](double x, double y, double s, double t) {
    const double p = x * y, q = s * t;
    return std::fabs(p - q) > 8 * detail::kUnitRoundoff * (std::fabs(p) + std::fabs(q)) + 0x1p-400;
  };
  return component(u[1], w[2], u[2], w[1]) || component(u[2], w[0], u[0], w[2]) || component(u[0], w[1], u[1], w[0]);
}
// a, b, c exactly on one line: exact differences, then exactly equal products.
inline bool exactly_collinear(const double* a, const double* b, const double* c) {
  double u[3], w[3];
  for (int k = 0; k < 3; ++k)
    if (!exact_difference(b[k], a[k], u[k]) || !exact_difference(c[k], a[k], w[k])) return false;
  return products_equal(u[1], w[2], u[2], w[1]) && products_equal(u[2], w[0], u[0], w[2]) && products_equal(u[0], w[1], u[1], w[0]);
}
// Most calls have no collinear triple, and floating point says so for each of the four at once:
// the differences from p0 are shared by three of them.
inline bool has_collinear_triple(const Coords<4>& p) {
  double d[3][3], e[2][3];
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) d[i][k] = p[i + 1][k] - p[0][k];
    e[0][k] = p[2][k] - p[1][k];
    e[1][k] = p[3][k] - p[1][k];
  }
  return (!cross_clearly_nonzero(d[0], d[1]) && exactly_collinear(p[0], p[1], p[2])) ||
         (!cross_clearly_nonzero(d[0], d[2]) && exactly_collinear(p[0], p[1], p[3])) ||
         (!cross_clearly_nonzero(d[1], d[2]) && exactly_collinear(p[0], p[2], p[3])) ||
         (!cross_clearly_nonzero(e[0], e[1]) && exactly_collinear(p[1], p[2], p[3]));
}

inline bool admissible(double max_abs_difference) {
  return max_abs_difference <= detail::kMaxFilteredDifference;  // false for NaN/inf too
}

// 2D: 2x2 determinant: 1 + 1 + 1 = 3 for the products, 4 after the subtraction.
constexpr double kOrient2Bound = 2.0 * 4 * detail::kUnitRoundoff;

Sign orient2(const Coords<3>& p) {
  const double acx = p[0][0] - p[2][0], acy = p[0][1] - p[2][1];
  const double bcx = p[1][0] - p[2][0], bcy = p[1][1] - p[2][1];
  const double left = acx * bcy, right = acy * bcx;
  const double det = left - right;
  const double largest = largest_magnitude(acx, acy, bcx, bcy);
  if (admissible(largest)) {
    const double bound = kOrient2Bound * (std::fabs(left) + std::fabs(right)) + detail::kUnderflowAbsoluteBound;
    if (det > bound) return detail::count_filtered(), Sign::Positive;
    if (det < -bound) return detail::count_filtered(), Sign::Negative;
  }
  if (share_a_coordinate(p, 2) || has_equal_points(p, 2)) return detail::count_filtered(), Sign::Zero;
  if (const auto sign = detail::orient2_small_range(p)) return detail::count_exact(), *sign;
  return detail::exact_sign(OrientFormula<2>{p});
}

// The stages after a failed filter, out of line so the filters stay small where they are inlined.
[[gnu::noinline]] Sign orient3_exact(const Coords<4>& p) {
  if (share_a_coordinate(p, 3) || has_equal_points(p, 3) || has_collinear_triple(p)) return detail::count_filtered(), Sign::Zero;
  if (const auto sign = detail::orient3_small_range(p)) return detail::count_exact(), *sign;
  return detail::exact_sign(OrientFormula<3>{p});
}
[[gnu::noinline]] Sign insphere3_exact(const Coords<5>& p) {
  if (has_equal_points(p, 3)) return detail::count_filtered(), Sign::Zero;
  return detail::exact_sign(InsphereFormula<3>{p});
}
// D = 4, after its hand-written filter: two equal points (a face through the sweep sphere's seed
// vertex, tested against it) give an exact zero that the wide integers would otherwise find (a tenth
// of a D = 4 sweep). D >= 5 has one generic filter-and-exact call, so there the test comes first.
template <int D, std::size_t N, class Formula>
[[gnu::noinline]] Sign exact_unless_repeated(const std::array<const double*, N>& p, const Formula& formula) {
  if (has_equal_points(p, D)) return detail::count_filtered(), Sign::Zero;
  return detail::exact_sign(formula);
}

// D >= 5, after the semi-static filter (filters_dd.h): two equal points, else the generic filter,
// whose bound is tighter, else the exact stage.
template <int D, std::size_t N, class Formula>
[[gnu::noinline]] Sign generic_sign(const std::array<const double*, N>& p, const Formula& formula) {
  if (has_equal_points(p, D)) return detail::count_filtered(), Sign::Zero;
  return detail::filtered_sign(formula);
}

// The sign a hand-written filter's estimate certifies (filters3.h, filters4.h), else exact().
template <class Exact>
inline Sign certified_or(const detail::Estimate& e, Exact&& exact) {
  if (e.value > e.error) return detail::count_filtered(), Sign::Positive;
  if (e.value < -e.error) return detail::count_filtered(), Sign::Negative;
  return exact();
}

}  // namespace

template <int D>
Sign orient(const Coords<D + 1>& p) {
  if constexpr (D == 2) return orient2(p);
  else if constexpr (D == 3) return certified_or(detail::orient3_estimate(p), [&] { return orient3_exact(p); });
  else if constexpr (D == 4) {
    const detail::Orient4Filter filter(p);  // the determinant once, the permanent only when needed
    return certified_or(filter.column_sums(), [&] {
      return certified_or(filter.permanent(), [&] { return exact_unless_repeated<4>(p, OrientFormula<4>{p}); });
    });
  }
  else return certified_or(detail::orient_estimate_dd<D>(p), [&] { return generic_sign<D>(p, OrientFormula<D>{p}); });
}

template <int D>
Sign insphere(const Coords<D + 2>& p) {
  if constexpr (D == 3) return certified_or(detail::insphere3_estimate(p), [&] { return insphere3_exact(p); });
  else if constexpr (D == 4) {
    const detail::Insphere4Filter filter(p);
    return certified_or(filter.column_sums(), [&] {
      return certified_or(filter.permanent(), [&] { return exact_unless_repeated<4>(p, InsphereFormula<4>{p}); });
    });
  }
  else return certified_or(detail::insphere_estimate_dd<D>(p), [&] { return generic_sign<D>(p, InsphereFormula<D>{p}); });
}

template <int D>
double orient_value(const Coords<D + 1>& p) {
  ExactArith exact;
  return OrientFormula<D>{p}(exact).to_double();
}

template <int D>
Sign orient_projected(const Coords<D>& p, int drop) {
  std::array<std::array<double, D - 1>, D> projected;
  Coords<D> q;
  for (int i = 0; i < D; ++i) {
    int col = 0;
    for (int axis = 0; axis < D; ++axis)
      if (axis != drop) projected[i][col++] = p[i][axis];
    q[i] = projected[i].data();
  }
  return orient<D - 1>(q);
}

#define SWEEPCDT_INSTANTIATE(D)                                  \
  template Sign orient<D>(const Coords<D + 1>&);                 \
  template Sign insphere<D>(const Coords<D + 2>&);               \
  template double orient_value<D>(const Coords<D + 1>&);
SWEEPCDT_INSTANTIATE(1)
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE
template <int D>
bool collinear(const double* a, const double* b, const double* c) {
  // Exactly collinear points (Steiner points on their segments) would take every projection to its
  // exact stage; exactly_collinear (above) says "yes" to most of them in a few dozen operations.
  if constexpr (D == 3)
    if (exactly_collinear(a, b, c)) return true;
  for (int i = 0; i < D; ++i)
    for (int j = i + 1; j < D; ++j) {
      const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
      if (orient<2>({pa, pb, pc}) != Sign::Zero) return false;
    }
  return true;
}

template bool collinear<2>(const double*, const double*, const double*);
template bool collinear<3>(const double*, const double*, const double*);
template bool collinear<4>(const double*, const double*, const double*);
template bool collinear<5>(const double*, const double*, const double*);
template Sign orient_projected<2>(const Coords<2>&, int);
template Sign orient_projected<3>(const Coords<3>&, int);
template Sign orient_projected<4>(const Coords<4>&, int);
template Sign orient_projected<5>(const Coords<5>&, int);

}  // namespace sweepcdt::predicates
