// Computing with the GIL released, while Python can still watch and stop the run.
//
// The computation runs on the calling thread with the GIL released (other Python threads run
// meanwhile). Whenever core reports progress, and at each phase of the module's own, the GIL is
// taken back briefly to check for signals (Ctrl-C: PyErr_CheckSignals runs Python's SIGINT handler,
// which raises KeyboardInterrupt) and to call the user's progress callback. Either raising, or the
// callback returning False, cancels: core unwinds with CancelledError and the Python exception is
// raised in its place (KeyboardInterrupt, the callback's own, or sweepcdt.CancelledError).
#pragma once
#include <pybind11/pybind11.h>

#include <cstdint>
#include <functional>
#include <optional>

#include "sweepcdt/cdt.h"

namespace sweepcdt::python {

namespace py = pybind11;

class Watch {
 public:
  explicit Watch(py::object callback) : callback_(std::move(callback)) {}
  Watch(const Watch&) = delete;
  Watch& operator=(const Watch&) = delete;

  // Called without the GIL. False: cancel (the reason is kept for rethrow()).
  bool report(const char* phase, uint64_t done, uint64_t total);
  // A phase of the module's own; throws CancelledError when the run is to stop.
  void phase(const char* name);
  // For Options::progress.
  std::function<bool(const Progress&)> core_callback();

  // With the GIL, after CancelledError: raises why the run stopped.
  [[noreturn]] void rethrow();

 private:
  py::object callback_;
  std::optional<py::error_already_set> error_;  // the Python exception that cancelled the run
};

}  // namespace sweepcdt::python
