// Counters of how predicates were decided: by the floating-point filter, by exact arithmetic, or by
// the symbolic perturbation. They count only when built with -DSWEEPCDT_PREDICATE_STATS=ON (CMake
// option of the same name); otherwise they stay zero and cost nothing. They explain why a degenerate
// input is slow.
#pragma once
#include <cstdint>

namespace sweepcdt::predicates {

struct PredicateStats {
  uint64_t filtered = 0;   // decided by a floating-point filter
  uint64_t exact = 0;      // needed the exact fallback
  uint64_t perturbed = 0;  // exactly zero, decided by the symbolic perturbation
};

bool predicate_stats_enabled();
PredicateStats predicate_stats();
void reset_predicate_stats();

}  // namespace sweepcdt::predicates
