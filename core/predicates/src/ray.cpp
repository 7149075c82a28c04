// Paper §3, "drop face": the ray test and the order of strikes along the ray.
#include "sweepcdt/predicates/ray.h"

#include <cmath>

#include "arith.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::predicates {

template <int D>
Coords<D + 1> with_point(const Coords<D>& f, const double* p);  // sweep_sides.cpp

// The ray strikes f iff f lies behind every other facet g_i of conv(f ∪ v) (g_i = f with f_i
// replaced by v). orient(g_i, f_i) is orient(f, v) with rows i and D swapped, i.e. -o: so f_i is
// behind g_i iff behind_sign(g_i) = -o, one orientation per facet instead of side_of()'s two.
template <int D, class Sweep>
bool ray_hits(const Sweep& sweep, const double* v, const Coords<D>& f) {
  const Sign o = orient<D>(with_point<D>(f, v));
  if (o == Sign::Zero) return false;  // conv(f ∪ v) degenerate
  for (int i = 0; i < D; ++i) {
    Coords<D> g = f;  // the hyperface of conv(f ∪ v) opposite f_i
    g[i] = v;
    if (behind_sign<D>(sweep, g) != -o) return false;
  }
  return true;
}

namespace {

// Along the ray x(t) = v + t d(delta), orient(f, x(t)) = o + t g(delta), with o = orient(f, v) and
// g(delta) = sum_j delta^j g_j, g_j = (gradient of orient(f, .)) . d_j. The strike is at t = -o / g.
// Plane: d_j = -e_j, so g_j = -n_j (normal components). Sphere: d_j = Delta_j - v, so
// g_j = orient(f, Delta_j) - o.
template <int D, class Arith>
typename Arith::T direction_term(Arith& a, const PlaneSweep&, const double*, const Coords<D>& f, int j) {
  return -detail::normal_component<D>(a, f, j);
}

template <int D, class Arith>
typename Arith::T direction_term(Arith& a, const SphereSweep<D>& sweep, const double* v, const Coords<D>& f, int j) {
  return detail::orient_det<D>(a, with_point<D>(f, sweep.delta[j])) - detail::orient_det<D>(a, with_point<D>(f, v));
}

template <int D, class Sweep>
Sign direction_sign(const Sweep& sweep, const double* v, const Coords<D>& f) {
  for (int j = 0; j < D + 1; ++j) {
    if constexpr (std::is_same_v<Sweep, PlaneSweep>)
      if (j == D) break;
    const Sign g = detail::filtered_sign([&](auto& a) { return direction_term<D>(a, sweep, v, f, j); });
    if (g != Sign::Zero) return g;
  }
  return Sign::Zero;
}

// Does f have a vertex at x? Then orient(f, x) = 0 exactly and, on the sphere, g_j = -o for
// x = Delta_j, so for two such faces the delta^j coefficient o2 g1_j - o1 g2_j = -o2 o1 + o1 o2 is
// identically zero: every ray toward a seed vertex Delta_0 strikes all faces around Delta_0 at t = 1,
// and the exact stage would evaluate that zero for each pair (an exact-zero fast path, no tolerance).
template <int D>
bool has_point(const Coords<D>& f, const double* x) {
  for (int i = 0; i < D; ++i) {
    bool equal = true;
    for (int k = 0; k < D && equal; ++k) equal = f[i][k] == x[k] && std::isfinite(x[k]);
    if (equal) return true;
  }
  return false;
}

}  // namespace

// t1 - t2 = (o2 g1 - o1 g2) / (g1 g2): the sign of the numerator is that of its first non-zero
// coefficient in delta, the denominator's that of the leading terms of g1 and g2.
template <int D, class Sweep>
Sign compare_hits(const Sweep& sweep, const double* v, const Coords<D>& f1, const Coords<D>& f2) {
  const Sign g1 = direction_sign<D>(sweep, v, f1), g2 = direction_sign<D>(sweep, v, f2);
  if (g1 == Sign::Zero || g2 == Sign::Zero) return Sign::Zero;  // a face parallel to every direction
  const int terms = std::is_same_v<Sweep, PlaneSweep> ? D : D + 1;
  for (int j = 0; j < terms; ++j) {
    if constexpr (!std::is_same_v<Sweep, PlaneSweep>)
      if (has_point<D>(f1, sweep.delta[j]) && has_point<D>(f2, sweep.delta[j])) continue;  // term j is 0
    const Sign n = detail::filtered_sign([&](auto& a) {
      const auto o1 = detail::orient_det<D>(a, with_point<D>(f1, v));
      const auto o2 = detail::orient_det<D>(a, with_point<D>(f2, v));
      return o2 * direction_term<D>(a, sweep, v, f1, j) - o1 * direction_term<D>(a, sweep, v, f2, j);
    });
    if (n != Sign::Zero) return n * g1 * g2;
  }
  return Sign::Zero;
}

#define SWEEPCDT_INSTANTIATE(D)                                                                        \
  template bool ray_hits<D, PlaneSweep>(const PlaneSweep&, const double*, const Coords<D>&);          \
  template bool ray_hits<D, SphereSweep<D>>(const SphereSweep<D>&, const double*, const Coords<D>&);  \
  template Sign compare_hits<D, PlaneSweep>(const PlaneSweep&, const double*, const Coords<D>&,       \
                                            const Coords<D>&);                                        \
  template Sign compare_hits<D, SphereSweep<D>>(const SphereSweep<D>&, const double*, const Coords<D>&, \
                                                const Coords<D>&);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::predicates
