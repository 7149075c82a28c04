// Region ids: the domain's parts separated by constraining simplices (paper §1: several components,
// cavities, non-manifold domains). A part holding a region seed takes the seed's id; the others are
// numbered after the largest seed id, in the order of their lowest simplex.
#pragma once
#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {

// Needs tri.neighbors. On `threads` threads (parallel.h); the result does not depend on their number.
template <int D>
void assign_regions(Triangulation<D>& tri, const Plc<D>& plc, unsigned threads);

}  // namespace sweepcdt::detail
