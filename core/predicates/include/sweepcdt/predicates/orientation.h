// Orientation and insphere tests in dimension D (instantiated for D = 1..5), exact for all finite
// double coordinates. Each runs a floating-point filter with a derived error bound and falls back to
// exact dyadic arithmetic (GMP) only when the filter cannot decide. D = 3 has hand-written filters.
//
// Conventions (the same as Shewchuk's predicates.c in 2D and 3D):
//   orient(p_0..p_D)      = sign det [p_i - p_D]_{i<D}          (= sign det [[p_i, 1]]_{i<=D})
//     D = 2: positive when p_0, p_1, p_2 are counterclockwise.
//     D = 3: positive when p_3 lies below the plane of p_0, p_1, p_2, seen counterclockwise from above.
//   insphere(p_0..p_{D+1}) = sign det [p_i - p_{D+1}, |p_i - p_{D+1}|^2]_{i<=D}
//     = sign det [[p_i, |p_i|^2, 1]]_{i<=D+1}: the lifted orientation in D+1 dimensions.
//     Positive when p_{D+1} lies inside the circumsphere of p_0..p_D and orient(p_0..p_D) > 0
//     (check: with p_{D+1} at the circumcentre the determinant is r^2 * orient(p_0..p_D)).
#pragma once
#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

template <int D>
Sign orient(const Coords<D + 1>& p);

template <int D>
Sign insphere(const Coords<D + 2>& p);

// The exact value det [p_i - p_D] (D! times the signed volume), rounded to the nearest double.
// For measures in tests and reports; never use it to decide a sign.
template <int D>
double orient_value(const Coords<D + 1>& p);

// Convenience overloads for vertices.
template <int D>
Sign orient(const Vertices<D + 1>& p) {
  return orient<D>(coords_of(p));
}

// Orientation of D points after dropping coordinate `drop` (0-based) from each point in R^D, i.e.
// the orientation of the projection onto the other D-1 axes. Used to work inside a hyperplane.
template <int D>
Sign orient_projected(const Coords<D>& p, int drop);

// Do a, b, c lie on one line (exactly)? Every 2x2 minor of (b - a, c - a) vanishes: the orientations
// of their projections onto the coordinate planes. D = 2..5.
template <int D>
bool collinear(const double* a, const double* b, const double* c);

}  // namespace sweepcdt::predicates
