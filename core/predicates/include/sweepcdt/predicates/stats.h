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

// Ties of D+2 cospherical points decided by the symbolic perturbation on the calling thread so far:
// in insphere_perturbed(), and in the sweep keys when the two simplices compared share a sphere (a
// sweep plane can find "no CDT" from such keys alone; keys that tie for other reasons are not
// counted, see sweep_keys.cpp). Counted always, unlike PredicateStats: cdt() reads it before and
// after a run that found no CDT, because only a run that met such a tie can end differently under
// another perturbation order (paper §6). Per thread, so that files meshed concurrently do not see
// each other's ties; cdt() runs on its caller's thread.
uint64_t perturbation_ties_on_this_thread();
// Credits ties that helper threads counted for work done on behalf of this one (core/src/parallel.h).
void add_perturbation_ties_on_this_thread(uint64_t ties);

}  // namespace sweepcdt::predicates
