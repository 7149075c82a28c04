// "Behind" and "in front of" a hyperplane, with the paper's tie-breaking (§3).
//
// Sweep plane: p is behind hyperplane h if it is on the side of (-inf, 0, ..., 0); if h is parallel to
//   x_1, on the side of (0, -inf, 0, ...), and so on through the axes.
// Sweep sphere: behind is the side holding Delta_0; if Delta_0 lies in h, the side holding Delta_1,
//   and so on through the vertices of the seed simplex Delta.
// Star sweep (paper §5, the CDT of a star-shaped polytope): the sweep runs inward, toward the point p
//   that sees the whole boundary, so behind is the side NOT holding p; if p lies in h, the side not
//   holding q_1, and so on (p perturbed toward q_1, q_2, ...: the same tie rule as the sphere's).
// All are stated through orient(f_0..f_{D-1}, p): behind_sign() is the sign that means "behind".
#pragma once
#include <array>
#include <cstdint>

#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

struct PlaneSweep {};

template <int D>
struct SphereSweep {
  Coords<D + 1> delta;  // the seed simplex Delta_0..Delta_D (non-degenerate)
};

template <int D>
struct StarSweep {
  // p, then the tie-breaking points q_1..q_{D+1}: among them D+1 affinely independent ones. p is
  // perturbed toward q_k (toward[k] = 1) or away from it (-1): a centre on the convex hull of a
  // deletion is perturbed away from a point inside, so that the new hull faces through it are seen
  // from outside (their simplices lie behind them).
  std::array<const double*, D + 2> centre;
  std::array<int8_t, D + 2> toward = all_toward();

  static constexpr std::array<int8_t, D + 2> all_toward() {
    std::array<int8_t, D + 2> t{};
    t.fill(1);
    return t;
  }
};

enum class Side : int8_t { Behind = -1, On = 0, Front = 1 };

// The sign of orient(f, p) for points p behind f. f must span a hyperplane.
template <int D>
Sign behind_sign(const PlaneSweep&, const Coords<D>& f);
template <int D>
Sign behind_sign(const SphereSweep<D>& sweep, const Coords<D>& f);

template <int D>
Sign behind_sign(const StarSweep<D>& sweep, const Coords<D>& f);

template <int D, class Sweep>
Side side_of(const Sweep& sweep, const Coords<D>& f, const double* p);

}  // namespace sweepcdt::predicates
