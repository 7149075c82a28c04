// Rotary order of faces around a ridge (paper §3, Figure 12).
#include "sweepcdt/predicates/rotary.h"

#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::predicates {
namespace {

template <int D>
Coords<D + 1> ridge_with(const Coords<D - 1>& ridge, const double* a, const double* b) {
  Coords<D + 1> s;
  for (int i = 0; i < D - 1; ++i) s[i] = ridge[i];
  s[D - 1] = a;
  s[D] = b;
  return s;
}

// 0: angle 0 (same half-hyperplane as ref), 1: (0, pi), 2: exactly pi, 3: (pi, 2 pi).
template <int D>
int half_turn(const Coords<D - 1>& ridge, const double* ref, const double* x) {
  const Sign o = orient<D>(ridge_with<D>(ridge, ref, x));
  if (o == Sign::Positive) return 1;
  if (o == Sign::Negative) return 3;
  return same_side_of_ridge<D>(ridge, ref, x) ? 0 : 2;
}

}  // namespace

// Within the hyperplane H through ridge and a, drop an axis along which H projects one-to-one
// (a non-zero normal component) and compare sides of the ridge in the projection.
template <int D>
bool same_side_of_ridge(const Coords<D - 1>& ridge, const double* a, const double* b) {
  Coords<D> with_a, with_b;
  for (int i = 0; i < D - 1; ++i) with_a[i] = with_b[i] = ridge[i];
  with_a[D - 1] = a;
  with_b[D - 1] = b;
  for (int drop = 0; drop < D; ++drop) {
    const Sign sa = orient_projected<D>(with_a, drop);
    if (sa == Sign::Zero) continue;
    return sa == orient_projected<D>(with_b, drop);
  }
  return false;  // ridge and a do not span a hyperplane
}

template <int D>
Sign compare_rotary(const Coords<D - 1>& ridge, const double* ref, const double* a, const double* b) {
  const int ha = half_turn<D>(ridge, ref, a), hb = half_turn<D>(ridge, ref, b);
  if (ha != hb) return ha < hb ? Sign::Negative : Sign::Positive;
  if (ha == 0 || ha == 2) return Sign::Zero;
  // Same open half-turn: b comes after a iff it is counterclockwise from a (orient > 0).
  return -orient<D>(ridge_with<D>(ridge, a, b));
}

#define SWEEPCDT_INSTANTIATE(D)                                                                   \
  template bool same_side_of_ridge<D>(const Coords<D - 1>&, const double*, const double*);        \
  template Sign compare_rotary<D>(const Coords<D - 1>&, const double*, const double*, const double*);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::predicates
