// The seed simplex of gift-wrapping (paper §2) when the PLC has no constraining simplex: a simplex of
// the perturbed Delaunay triangulation incident to point 0, found among its nearest neighbours and
// verified exactly against every point. The distance order only decides which candidates are tried
// first; the answer is decided by perturbed insphere tests alone. With K candidates doubling up to
// all points, it always finds one when the points span E^D.
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "sweepcdt/plc.h"

namespace sweepcdt::detail {

// A positively oriented D-simplex, or nothing when all points lie in one hyperplane.
template <int D>
std::optional<std::array<uint32_t, D + 1>> delaunay_seed(const Plc<D>& plc);

}  // namespace sweepcdt::detail
