#include "running.h"

namespace sweepcdt::python {

bool Watch::report(const char* phase, uint64_t done, uint64_t total) {
  py::gil_scoped_acquire gil;
  if (error_) return false;
  if (PyErr_CheckSignals() != 0) {
    error_.emplace();  // fetches KeyboardInterrupt (or whatever a signal handler raised)
    return false;
  }
  if (callback_.is_none()) return true;
  try {
    const py::object answer = callback_(phase, done, total);
    // Only an explicit False stops: a callback that returns nothing means "go on".
    return !(py::isinstance<py::bool_>(answer) && !answer.cast<bool>());
  } catch (py::error_already_set& e) {
    error_.emplace(std::move(e));
    return false;
  }
}

void Watch::phase(const char* name) {
  if (!report(name, 0, 0)) throw CancelledError();
}

std::function<bool(const Progress&)> Watch::core_callback() {
  return [this](const Progress& p) { return report(p.phase, p.done, p.total); };
}

void Watch::rethrow() {
  if (error_) throw *error_;
  const py::object type = py::module_::import("sweepcdt.errors").attr("CancelledError");
  PyErr_SetString(type.ptr(), "cancelled: the progress callback returned False");
  throw py::error_already_set();
}

}  // namespace sweepcdt::python
