// "Behind" and "in front of" a hyperplane, with the paper's tie-breaking (§3).
//
// Sweep plane: p is behind hyperplane h if it is on the side of (-inf, 0, ..., 0); if h is parallel to
//   x_1, on the side of (0, -inf, 0, ...), and so on through the axes.
// Sweep sphere: behind is the side holding Delta_0; if Delta_0 lies in h, the side holding Delta_1,
//   and so on through the vertices of the seed simplex Delta.
// Both are stated through orient(f_0..f_{D-1}, p): behind_sign() is the sign that means "behind".
#pragma once
#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

struct PlaneSweep {};

template <int D>
struct SphereSweep {
  Coords<D + 1> delta;  // the seed simplex Delta_0..Delta_D (non-degenerate)
};

enum class Side : int8_t { Behind = -1, On = 0, Front = 1 };

// The sign of orient(f, p) for points p behind f. f must span a hyperplane.
template <int D>
Sign behind_sign(const PlaneSweep&, const Coords<D>& f);
template <int D>
Sign behind_sign(const SphereSweep<D>& sweep, const Coords<D>& f);

template <int D, class Sweep>
Side side_of(const Sweep& sweep, const Coords<D>& f, const double* p);

}  // namespace sweepcdt::predicates
