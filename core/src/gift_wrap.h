// Naive gift-wrapping of a CDT (paper §2), any dimension. The reference the sweeps are tested against.
#pragma once
#include <array>
#include <cstdint>

#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

// Simplices of the CDT of a checked PLC (no regions, no neighbours yet). Throws NoCdtError when a
// face cannot be finished or would be finished twice, CancelledError on request.
template <int D>
Triangulation<D> gift_wrap(const Plc<D>& plc, const Options& options);

// One constrained Delaunay simplex, positively oriented, grown as gift-wrapping's first seed: the
// sweep sphere's Delta (paper §3: "construct one constrained Delaunay d-simplex by naive
// gift-wrapping").
template <int D>
std::array<uint32_t, D + 1> seed_simplex(const Plc<D>& plc);

}  // namespace sweepcdt::detail
