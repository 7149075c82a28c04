// A Delaunay triangulation computed on a helper thread while the calling thread does other work
// that does not need it: cdt() checks the PLC meanwhile (the cavity sweep starts from the mesh), and
// refinement groups the facets (steiner/refine.cpp starts from DelaunayEdges). On two cores the other
// work then costs no time of its own. When the caller ends early (a PLC the check rejects, an error,
// a cancel), the helper is told to stop and its work is thrown away. The triangulation is a pure
// function of the points (delaunay.h), so the result does not depend on this.
#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "delaunay.h"

namespace sweepcdt::detail {

// `make(inserted)` on a helper thread, where make builds a triangulation and calls inserted(points so
// far) every 1024 insertions (delaunay_mesh, DelaunayEdges); `inserted` throws when the helper is to stop.
template <class Result>
class InBackground {
 public:
  using Inserted = std::function<void(std::size_t)>;
  explicit InBackground(std::function<Result(const Inserted&)> make)
      : thread_([this, make = std::move(make)] {
          try {
            result_.emplace(make([this](std::size_t inserted) {
              inserted_.store(inserted, std::memory_order_relaxed);
              if (stop_.load(std::memory_order_relaxed)) throw Stopped();
            }));
          } catch (...) {
            // stopped, or no tetrahedralization (e.g. all points in one plane): the caller computes
            // it, or fails, without the helper
          }
          std::lock_guard lock(mutex_);
          done_ = true;
          finished_.notify_all();
        }) {}
  ~InBackground() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  InBackground(const InBackground&) = delete;
  InBackground& operator=(const InBackground&) = delete;

  // Tells the helper to stop (at its next report of progress); its result is then thrown away.
  void stop() { stop_ = true; }

  // Waits for the helper: its result, or null when it found none. Meanwhile, and once at the end,
  // `report(inserted)` is called on this thread with the points inserted so far; when it returns
  // false the helper is stopped and get() returns null (the caller cancels).
  template <class Report>
  Result* get(Report&& report) {
    {
      std::unique_lock lock(mutex_);
      while (!done_) {
        finished_.wait_for(lock, std::chrono::milliseconds(100));
        if (done_) break;
        lock.unlock();
        const bool go_on = report(inserted_.load(std::memory_order_relaxed));
        lock.lock();
        if (!go_on) {
          stop_ = true;
          break;
        }
      }
    }
    if (thread_.joinable()) thread_.join();
    if (!stop_ && !report(inserted_.load(std::memory_order_relaxed))) stop_ = true;  // at least one report
    return stop_ ? nullptr : result_ ? &*result_ : nullptr;
  }

 private:
  struct Stopped {};
  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> inserted_{0};
  std::mutex mutex_;
  std::condition_variable finished_;
  bool done_ = false;
  std::optional<Result> result_;
  std::thread thread_;  // last: starts once the members it uses exist
};

// The cavity sweep's: the mesh of `points` (n x D; they must outlive this object and not change).
template <int D>
class DelaunayInBackground : public InBackground<DelaunayMesh> {
 public:
  explicit DelaunayInBackground(const std::vector<double>& points)
      : InBackground<DelaunayMesh>(
            [&points](const Inserted& inserted) { return delaunay_mesh<D>(points, inserted); }) {}
};

}  // namespace sweepcdt::detail
