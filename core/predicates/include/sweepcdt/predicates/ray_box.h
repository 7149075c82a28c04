// Does the ray from v (sweep-plane: along -x_1; sweep-sphere: through Delta_0) meet a closed
// axis-aligned box? Used to prune drop-face searches (paper §3) with a bounding-box tree. Exact and
// conservative: closed boxes, so the tie-breaking perturbation of the ray can only remove hits.
#pragma once
#include "sweepcdt/predicates/sweep_sides.h"

namespace sweepcdt::predicates {

template <int D>
bool ray_meets_box(const PlaneSweep&, const double* v, const double* lo, const double* hi);

template <int D>
bool ray_meets_box(const SphereSweep<D>& sweep, const double* v, const double* lo, const double* hi);

}  // namespace sweepcdt::predicates
