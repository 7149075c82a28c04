// SWEEPCDT (paper §3, Figure 13) with a sweep plane or a sweep sphere.
#pragma once
#include <array>
#include <optional>

#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

// Simplices of the CDT of a checked PLC. `delta` is the seed simplex for the sphere (required) and
// must be empty for the plane, which needs a facet-bounded PLC. Throws NoCdtError, CancelledError.
template <int D>
Triangulation<D> sweep_cdt(const Plc<D>& plc, const std::optional<std::array<uint32_t, D + 1>>& delta,
                           const Options& options, CdtStatistics& stats);

// Paper §5: simplices of the CDT of a checked PLC whose notated constraints bound a polytope that is
// star-shaped from `centre` (sweepcdt/star_cdt.h). Throws NoCdtError, CancelledError. `open`: the
// polytope is the link of a vertex on the convex hull (paper §5: "works correctly even if v lies on
// the boundary of the CDT"); its constraints need not all get a simplex, the caller checks the result.
// `away`: a point strictly inside the domain left; the centre is perturbed away from it, so that new
// hull faces through the centre have their simplices behind them. `failure`: when given, the
// commonest way of finding no CDT — a simplex in front of a face built after it (Theorem 5) — is
// stored there and an empty triangulation returned instead of thrown (vertex deletion meets it in
// most refused attempts, where unwinding cost as much as a small star); other failures still throw.
template <int D>
Triangulation<D> star_sweep_cdt(const Plc<D>& plc, const std::array<double, D>& centre, const Options& options,
                                CdtStatistics& stats, bool open = false, const std::array<double, D>* away = nullptr,
                                std::optional<NoCdtError>* failure = nullptr);

}  // namespace sweepcdt::detail
