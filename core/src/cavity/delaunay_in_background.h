// The Delaunay tetrahedralization of a PLC's points, computed on a helper thread while the calling
// thread checks the PLC (cdt()): the check does not need it and the cavity sweep starts from it, so
// on two cores the check costs no time of its own. On a PLC the check rejects, the helper is told to
// stop and its work is thrown away. The mesh is a pure function of the points (delaunay3.h), so the
// result does not depend on this.
#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "../steiner/delaunay3.h"

namespace sweepcdt::detail {

class DelaunayInBackground {
 public:
  // Starts on `points` (which must outlive this object and not change).
  explicit DelaunayInBackground(const std::vector<double>& points)
      : thread_([this, &points] {
          try {
            mesh_ = delaunay_mesh(points, [this](std::size_t inserted) {
              inserted_.store(inserted, std::memory_order_relaxed);
              if (stop_.load(std::memory_order_relaxed)) throw Stopped();
            });
          } catch (...) {
            // stopped, or no tetrahedralization (e.g. all points in one plane): the caller computes
            // it, or fails, without the helper
          }
          std::lock_guard lock(mutex_);
          done_ = true;
          finished_.notify_all();
        }) {}
  ~DelaunayInBackground() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  DelaunayInBackground(const DelaunayInBackground&) = delete;
  DelaunayInBackground& operator=(const DelaunayInBackground&) = delete;

  // Waits for the helper: its mesh, or null when it found none. Meanwhile, and once at the end,
  // `report(inserted)` is called on this thread with the points inserted so far; when it returns
  // false the helper is stopped and get() returns null (the caller cancels).
  template <class Report>
  const DelaunayMesh* get(Report&& report) {
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
    return stop_ ? nullptr : mesh_ ? &*mesh_ : nullptr;
  }

 private:
  struct Stopped {};
  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> inserted_{0};
  std::mutex mutex_;
  std::condition_variable finished_;
  bool done_ = false;
  std::optional<DelaunayMesh> mesh_;
  std::thread thread_;  // last: starts once the members it uses exist
};

}  // namespace sweepcdt::detail
