// Internal: bump the predicate counters (no-ops unless built with SWEEPCDT_PREDICATE_STATS, except
// count_tie()).
#pragma once

namespace sweepcdt::predicates::detail {

// A tie decided by the perturbation, counted per thread whatever the build (stats.h).
void count_tie();

#ifdef SWEEPCDT_PREDICATE_STATS
void count_filtered();
void count_exact();
void count_perturbed();
#else
inline void count_filtered() {}
inline void count_exact() {}
inline void count_perturbed() {}
#endif

}  // namespace sweepcdt::predicates::detail
