// Naive gift-wrapping of a CDT (paper §2), any dimension. The reference the sweeps are tested against.
#pragma once
#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

// Simplices of the CDT of a checked PLC (no regions, no neighbours yet). Throws NoCdtError when a
// face cannot be finished or would be finished twice, CancelledError on request.
template <int D>
Triangulation<D> gift_wrap(const Plc<D>& plc, const Options& options);

}  // namespace sweepcdt::detail
