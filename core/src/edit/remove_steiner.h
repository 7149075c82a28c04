// Steiner points the CDT does not need after all (issue 17): refinement (steiner/refine.h) splits
// every segment that is not Delaunay, but a CDT often exists without many of those points. Each is
// deleted again (paper §5, EditableCdt) when the PLC left still has a CDT — the deletion checks
// that exactly and is undone otherwise — from a work list that holds every point first, spread
// out in bit-reversed order of creation (a point that stays is tried again when a neighbour that
// bears on its refusal goes). The next deletions of the list are worked out on
// `options.threads` threads and applied in list order: the result is one thread's.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

// Below this many Steiner points one thread deletes them: the threads' waiting for each other and
// the plans gone stale cost more than a second thread gains (box_fused_sphere_fine.stl: 509 points,
// 12% slower on two).
inline constexpr uint32_t kPointsForThreads = 1024;

// Points rounded off their segments (corners of facets bent by rounding) are deleted only from
// stars of at most this many tetrahedra (EditableCdt::unbend_facets_at_steiner_points; a Steiner
// point's own star has 15-25): larger ones are stars merged from deleted neighbours, where the exact
// predicates on nearly coplanar points cost many times as much (gearwheel_ascii.stl: 3801 points
// kept in 118 s unbounded, before the double-word predicate stage; 7189 in 7.3 s at 32, after it).
inline constexpr std::size_t kLargestBentStar = 32;

// A deletion may fill its cavity with at most this many times the point's star's tetrahedra, plus 8
// (EditableCdt::limit_growth). Measured in session 37 against no limit: 2 kept 102 more points on
// gearwheel_ascii.stl, 3 nine fewer; both cut perforated_tube_std's tetrahedra by more than half.
inline constexpr unsigned kGrowthFactor = 3;

struct SteinerDeletions {
  uint64_t removed = 0, tried = 0, skipped = 0;  // points deleted, deletions tried, retries skipped
  uint64_t refused_early = 0;  // of those tried: refused before the cavity was built (EditableCdt::refused_early)
};

// `tri` is the CDT of `plc` (the refined PLC: tri.num_input_points input points, then Steiner
// points); both are replaced by the result. `made_from`: per Steiner point, the two points it was
// made from (refine.h); `sweepcdt check` recognises a Steiner point as a rounded split of those
// two, so a point stays while a point made from it stays. (A point on a segment is made from the
// segment's input ends when their difference is exact; only points on other segments and fold
// points are made from Steiner points.) `off_input`: per constraint of `plc`, whether its facet holds
// a point off the facet's plane (RefinedPlc::off_input); the others' pieces are flat. Throws
// CancelledError when `options.progress` says so.
SteinerDeletions remove_steiner_points(Triangulation<3>& tri, Plc<3>& plc, const std::vector<std::array<uint32_t, 2>>& made_from,
                               const std::vector<char>& off_input, const Options& options);

}  // namespace sweepcdt::detail
