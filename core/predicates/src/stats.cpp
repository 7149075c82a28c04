#include "sweepcdt/predicates/stats.h"

#include <atomic>

#include "stats_counters.h"

namespace sweepcdt::predicates {

namespace {
// A count private to each thread, read by cdt() as a difference: no state any result depends on.
thread_local uint64_t t_ties = 0;
}  // namespace

void detail::count_tie() { ++t_ties; }
uint64_t perturbation_ties_on_this_thread() { return t_ties; }
void add_perturbation_ties_on_this_thread(uint64_t ties) { t_ties += ties; }

#ifdef SWEEPCDT_PREDICATE_STATS
namespace {
std::atomic<uint64_t> g_filtered{0}, g_exact{0}, g_perturbed{0};
}
namespace detail {
void count_filtered() { g_filtered.fetch_add(1, std::memory_order_relaxed); }
void count_exact() { g_exact.fetch_add(1, std::memory_order_relaxed); }
void count_perturbed() { g_perturbed.fetch_add(1, std::memory_order_relaxed); }
}  // namespace detail
bool predicate_stats_enabled() { return true; }
PredicateStats predicate_stats() { return {g_filtered.load(), g_exact.load(), g_perturbed.load()}; }
void reset_predicate_stats() {
  g_filtered = 0;
  g_exact = 0;
  g_perturbed = 0;
}
#else
bool predicate_stats_enabled() { return false; }
PredicateStats predicate_stats() { return {}; }
void reset_predicate_stats() {}
#endif

}  // namespace sweepcdt::predicates
