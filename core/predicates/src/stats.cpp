#include "sweepcdt/predicates/stats.h"

#include <atomic>

#include "stats_counters.h"

namespace sweepcdt::predicates {

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
