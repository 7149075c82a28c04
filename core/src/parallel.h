// Internal: deterministic data parallelism for the exact checks (the PLC check, validate()).
// [0, n) is cut into contiguous parts, one per thread; each part writes only its own result, and
// the caller combines the results in part order — so the answer, down to the order of reported
// problems, is the same for any number of threads. Ties the helper threads' predicates decide by
// the perturbation are credited to the calling thread (cdt() reads that count to decide whether
// another perturbation order may help, paper §6).
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "sweepcdt/predicates/stats.h"

namespace sweepcdt::detail {

// `requested` threads, or the hardware's when 0. (Asked once: glibc reads a /sys file each time, and
// the deletion pass validates tens of thousands of small cavities.)
inline unsigned thread_count(unsigned requested) {
  if (requested) return requested;
  static const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  return hardware;
}

// Work below this many items a part is not worth a thread.
inline constexpr std::size_t kItemsPerThread = 4096;

// The number of parts for_each_part() cuts n items into (`per_thread`: fewer for costlier items).
inline std::size_t parts_for(std::size_t n, unsigned threads, std::size_t per_thread = kItemsPerThread) {
  if (n < 2 * per_thread) return 1;
  return std::max<std::size_t>(1, std::min<std::size_t>(thread_count(threads), n / per_thread));
}

// body(part, begin, end) for each of parts_for(n, threads, per_thread) contiguous parts of [0, n);
// the calling thread runs part 0. The first exception of a part (in part order) is rethrown once
// all are done.
template <class Body>
void for_each_part(std::size_t n, unsigned threads, Body&& body, std::size_t per_thread = kItemsPerThread) {
  const std::size_t parts = parts_for(n, threads, per_thread);
  const auto range = [&](std::size_t part) { return std::pair{n * part / parts, n * (part + 1) / parts}; };
  if (parts == 1) {
    body(std::size_t{0}, std::size_t{0}, n);
    return;
  }
  std::vector<std::exception_ptr> errors(parts);
  std::vector<uint64_t> ties(parts, 0);
  std::vector<std::thread> workers;
  for (std::size_t part = 1; part < parts; ++part)
    workers.emplace_back([&, part] {
      const uint64_t before = predicates::perturbation_ties_on_this_thread();
      try {
        const auto [begin, end] = range(part);
        body(part, begin, end);
      } catch (...) {
        errors[part] = std::current_exception();
      }
      ties[part] = predicates::perturbation_ties_on_this_thread() - before;
    });
  try {
    const auto [begin, end] = range(0);
    body(std::size_t{0}, begin, end);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (std::thread& w : workers) w.join();
  for (const uint64_t t : ties) predicates::add_perturbation_ties_on_this_thread(t);
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

// first() on this thread while second() runs on a helper, given two threads (else one after the
// other, in that order): for two pieces of work that share nothing they write. for_each_part's two
// parts, so the first exception, first()'s before second()'s, is rethrown once both are done, and
// second()'s perturbation ties are credited to the calling thread.
template <class First, class Second>
void side_by_side(bool on_two_threads, First&& first, Second&& second) {
  for_each_part(2, on_two_threads ? 2 : 1, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t job = begin; job < end; ++job) job == 0 ? first() : second();
  }, 1);
}

// Threads kept for many small jobs: the deletion pass works out thousands of vertex deletions of a
// fraction of a millisecond each, where starting a thread per batch would cost as much as the work.
// run(n, job) calls job(i) once for every i in [0, n), spread over the helpers and the calling
// thread, and returns when all are done. `job` must not throw. Ties the helpers' predicates decide
// by the perturbation are credited to the calling thread, as for_each_part() does.
class WorkerPool {
 public:
  explicit WorkerPool(unsigned helpers) {
    for (unsigned k = 0; k < helpers; ++k) helpers_.emplace_back([this] { serve(); });
  }
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  ~WorkerPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
      generation_.fetch_add(1);
    }
    wake_.notify_all();
    for (std::thread& t : helpers_) t.join();
  }

  // `while_waiting`, if given, is called on this thread every 50 ms or so while it waits for the
  // helpers after its own share of the jobs; it must not throw either. (The cavity sweep reports
  // progress there: progress is reported on the caller's thread only, and a caller that cancels
  // must be heard while a helper sweeps a large cavity.)
  //
  // `extra`, if given, is called on this thread, once its share is done, again and again while a
  // helper is still busy, until it returns false: work that may be done meanwhile or not at all
  // (the deletion pass plans further deletions there instead of waiting for the batch's last one).
  void run(std::size_t n, const std::function<void(std::size_t)>& job, const std::function<void()>& while_waiting = {},
           const std::function<bool()>& extra = {}) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &job;
      n_ = n;
      next_ = 0;
      busy_ = helpers_.size();
      ties_ = 0;
      generation_.fetch_add(1);
    }
    wake_.notify_all();
    take_jobs();
    if (extra)
      while (busy_.load() != 0 && extra()) {
      }
    // The jobs are a fraction of a millisecond: spin a little before sleeping on the condition.
    for (int spin = 0; spin < kSpins && busy_.load() != 0; ++spin) std::this_thread::yield();
    std::unique_lock<std::mutex> lock(mutex_);
    const auto all_done = [&] { return busy_.load() == 0; };
    if (!while_waiting) done_.wait(lock, all_done);
    while (while_waiting && !done_.wait_for(lock, std::chrono::milliseconds(50), all_done)) {
      lock.unlock();
      while_waiting();
      lock.lock();
    }
    job_ = nullptr;
    predicates::add_perturbation_ties_on_this_thread(ties_);
  }

 private:
  static constexpr int kSpins = 2000;
  void take_jobs() {
    for (std::size_t i; (i = next_.fetch_add(1)) < n_;) (*job_)(i);
  }
  void serve() {
    uint64_t seen = 0;
    for (;;) {
      for (int spin = 0; spin < kSpins && generation_.load() == seen; ++spin) std::this_thread::yield();
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return generation_.load() != seen; });
      if (stopping_) return;
      seen = generation_.load();
      lock.unlock();
      const uint64_t before = predicates::perturbation_ties_on_this_thread();
      take_jobs();
      const uint64_t ties = predicates::perturbation_ties_on_this_thread() - before;
      lock.lock();
      ties_ += ties;
      if (busy_.fetch_sub(1) == 1) done_.notify_one();
    }
  }

  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  bool stopping_ = false;
  std::atomic<uint64_t> generation_{0};
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t n_ = 0;
  std::atomic<std::size_t> next_{0};
  std::atomic<std::size_t> busy_{0};
  uint64_t ties_ = 0;
};

// Appends what a later part found to what the earlier parts found, as one scan in order would have
// listed it: `items` keeps the first `limit` of each kind, `counts` counts them all. `kind_of(item)`
// names an item's kind. Both the PLC check's problems and validate()'s failures are merged so.
template <class Item, class Kind, class KindOf>
void append_part(std::vector<Item>& items, std::map<Kind, std::size_t>& counts, std::vector<Item>&& later_items,
                 const std::map<Kind, std::size_t>& later_counts, std::size_t limit, KindOf&& kind_of) {
  std::map<Kind, std::size_t> kept;  // of later_counts, those listed in later_items
  for (Item& item : later_items) {
    const Kind kind = kind_of(item);
    ++kept[kind];
    if (counts[kind]++ < limit) items.push_back(std::move(item));
  }
  for (const auto& [kind, count] : later_counts) counts[kind] += count - kept[kind];
}

}  // namespace sweepcdt::detail
