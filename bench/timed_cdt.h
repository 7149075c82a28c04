// cdt() run `repeat` times and timed, for the benchmark drivers (sweep_bench, dd_bench).
#pragma once
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "sweepcdt/cdt.h"

namespace sweepcdt::bench {

struct TimedCdt {
  double median_seconds = -1;  // -1 when the first run failed
  std::size_t simplices = 0;
  std::string error;           // the first failure's message
  CdtStatistics stats;         // the last run's (cdt() resets its statistics)
  double peak_rss_mb = 0;      // of the whole process so far
};

template <int D>
TimedCdt timed_cdt(const Plc<D>& plc, Options options, int repeat) {
  TimedCdt result;
  options.statistics = &result.stats;
  std::vector<double> seconds;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    try {
      result.simplices = cdt(plc, options).num_simplices();
    } catch (const std::exception& e) {
      result.error = e.what();
      break;
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  if (!seconds.empty()) result.median_seconds = seconds[seconds.size() / 2];
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  result.peak_rss_mb = usage.ru_maxrss / 1024.0;
  return result;
}

}  // namespace sweepcdt::bench
