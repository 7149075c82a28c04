// The drop-face ray test of SWEEPCDT (paper §3, "drop face", Figures 10 and 11).
//
// The ray from v points along -x_1 (sweep plane) or toward Delta_0 (sweep sphere). Ties are broken
// lexicographically, which amounts to the symbolically perturbed direction
//   d(delta) = sum_j delta^j d_j   (plane: d_j = -e_{j+1};  sphere: d_j = Delta_j - v)
// for an infinitesimal delta > 0 — the same rule that defines "behind".
#pragma once
#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/sweep_sides.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

// Does the open ray from v strike the (D-1)-simplex f? Following the paper, a strike counts exactly
// when conv(f ∪ v) is non-degenerate and lies behind all D of its hyperfaces incident on v; for the
// perturbed direction this is "the ray passes through f", boundary hits included or not as the
// tie-breaking decides.
template <int D, class Sweep>
bool ray_hits(const Sweep& sweep, const double* v, const Coords<D>& f);

// For two faces that the ray from v strikes: Negative when f1 is struck first, Positive when f2 is,
// Zero when they are struck at the same point for every tie-breaking direction (coplanar faces).
template <int D, class Sweep>
Sign compare_hits(const Sweep& sweep, const double* v, const Coords<D>& f1, const Coords<D>& f2);

}  // namespace sweepcdt::predicates
