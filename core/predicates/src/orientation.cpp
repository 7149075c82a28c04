// orient and insphere for D = 1..5: generic formulas through filtered_sign(), and hand-written 3D
// filters (the hot path of tetrahedralization) with constexpr bounds derived as in approx.h.
#include "sweepcdt/predicates/orientation.h"

#include <algorithm>
#include <cmath>

#include "arith.h"

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

// --- 3D filters -------------------------------------------------------------------------------
// Rounding counts (see approx.h): differences 1; 2x2 minors 1+1+1 = 3 then the subtraction 4;
// 3x3 determinant: 4 + 1 + 1 = 6 per term, two sequential additions: 8.
constexpr double kOrient3Bound = 2.0 * 8 * detail::kUnitRoundoff;
// insphere: lifts 3 (square) then two additions: 5; 3x3 minors 8 as above; lift * minor: 5+8+1 = 14;
// (x - y) + (z - w): two more levels: 16.
constexpr double kInsphere3Bound = 2.0 * 16 * detail::kUnitRoundoff;

// max(|x|) over the arguments by plain comparisons (std::fmax is a libm call here). A NaN may be
// dropped: the determinant is then NaN too, fails the filter, and the exact stage reports it.
template <class... T>
inline double largest_magnitude(T... x) {
  double m = 0.0;
  ((m = std::fabs(x) > m ? std::fabs(x) : m), ...);
  return m;
}

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
  if (has_equal_points(p, 2)) return detail::count_filtered(), Sign::Zero;
  return detail::exact_sign(OrientFormula<2>{p});
}

// The stages after a failed filter, out of line so the filters stay small where they are inlined.
[[gnu::noinline]] Sign orient3_exact(const Coords<4>& p) {
  if (has_equal_points(p, 3)) return detail::count_filtered(), Sign::Zero;
  return detail::exact_sign(OrientFormula<3>{p});
}
[[gnu::noinline]] Sign insphere3_exact(const Coords<5>& p) {
  if (has_equal_points(p, 3)) return detail::count_filtered(), Sign::Zero;
  return detail::exact_sign(InsphereFormula<3>{p});
}

Sign orient3(const Coords<4>& p) {
  const double* a = p[0];
  const double* b = p[1];
  const double* c = p[2];
  const double* d = p[3];
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];

  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  const double largest = largest_magnitude(adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz);
  if (admissible(largest)) {
    const double bound = kOrient3Bound * permanent + detail::kUnderflowAbsoluteBound;
    if (det > bound) return detail::count_filtered(), Sign::Positive;
    if (det < -bound) return detail::count_filtered(), Sign::Negative;
  }
  return orient3_exact(p);
}

Sign insphere3(const Coords<5>& p) {
  const double* e = p[4];
  double dx[4], dy[4], dz[4], lift[4], largest = 0.0;
  for (int i = 0; i < 4; ++i) {
    dx[i] = p[i][0] - e[0];
    dy[i] = p[i][1] - e[1];
    dz[i] = p[i][2] - e[2];
    lift[i] = dx[i] * dx[i] + dy[i] * dy[i] + dz[i] * dz[i];
    largest = std::max(largest, largest_magnitude(dx[i], dy[i], dz[i]));
  }
  // 2x2 minors of the x,y columns for rows (i, j).
  auto minor2 = [&](int i, int j) { return dx[i] * dy[j] - dx[j] * dy[i]; };
  auto minor2_abs = [&](int i, int j) { return std::fabs(dx[i] * dy[j]) + std::fabs(dx[j] * dy[i]); };
  // 3x3 minors det[r_i; r_j; r_k] of the x,y,z columns, expanded along z.
  auto minor3 = [&](int i, int j, int k) {
    return dz[i] * minor2(j, k) - dz[j] * minor2(i, k) + dz[k] * minor2(i, j);
  };
  auto minor3_abs = [&](int i, int j, int k) {
    return std::fabs(dz[i]) * minor2_abs(j, k) + std::fabs(dz[j]) * minor2_abs(i, k) +
           std::fabs(dz[k]) * minor2_abs(i, j);
  };
  // Expansion along the lift column (rows a=0, b=1, c=2, d=3), as in Shewchuk's insphere.
  const double abc = minor3(0, 1, 2), bcd = minor3(1, 2, 3), cda = minor3(2, 3, 0), dab = minor3(3, 0, 1);
  const double det = (lift[3] * abc - lift[2] * dab) + (lift[1] * cda - lift[0] * bcd);
  const double permanent = (lift[3] * minor3_abs(0, 1, 2) + lift[2] * minor3_abs(3, 0, 1)) +
                           (lift[1] * minor3_abs(2, 3, 0) + lift[0] * minor3_abs(1, 2, 3));
  if (admissible(largest)) {
    const double bound = kInsphere3Bound * permanent + detail::kUnderflowAbsoluteBound;
    if (det > bound) return detail::count_filtered(), Sign::Positive;
    if (det < -bound) return detail::count_filtered(), Sign::Negative;
  }
  return insphere3_exact(p);
}

}  // namespace

template <int D>
Sign orient(const Coords<D + 1>& p) {
  if constexpr (D == 2) return orient2(p);
  else if constexpr (D == 3) return orient3(p);
  else return detail::filtered_sign(OrientFormula<D>{p});
}

template <int D>
Sign insphere(const Coords<D + 2>& p) {
  if constexpr (D == 3) return insphere3(p);
  else return detail::filtered_sign(InsphereFormula<D>{p});
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
