// Internal: bump the predicate counters (no-ops unless built with SWEEPCDT_PREDICATE_STATS).
#pragma once

namespace sweepcdt::predicates::detail {

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
