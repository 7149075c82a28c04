#include "errors.h"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <new>

#include "sweepcdt/cdt.h"
#include "sweepcdt/editable_cdt.h"
#include "sweepcdt/io/error.h"

namespace sweepcdt::python {
namespace py = pybind11;
namespace {

// sweepcdt.errors.<name>(message) with the given attributes.
py::object exception(const char* name, const std::string& message, const py::dict& attributes = {}) {
  const py::object error = py::module_::import("sweepcdt.errors").attr(name)(message);
  for (const auto& [key, value] : attributes) py::setattr(error, key, value);
  return error;
}

// Sets the Python error to that exception.
void raise(const char* name, const std::string& message, const py::dict& attributes = {}) {
  const py::object error = exception(name, message, attributes);
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
}

template <class Problem, class KindName>
py::list problems_of(const std::vector<Problem>& problems, KindName kind_name) {
  py::list out;
  for (const Problem& p : problems)
    out.append(py::make_tuple(kind_name(p.kind), py::cast(p.elements), p.message));
  return out;
}

std::string ids_text(const std::vector<uint32_t>& ids) {
  std::string s;
  for (uint32_t id : ids) s += (s.empty() ? "" : " ") + std::to_string(id);
  return s;
}

std::string no_cdt_message(const NoCdtError& e) {
  std::string message = e.what();
  // As the converter says it: the ids are the welded input's (an EditableCdt's own ids).
  if (!e.witness().empty()) message += " (witness vertices " + ids_text(e.witness()) + ", 0-based input ids)";
  return message;
}

void translate(std::exception_ptr p) {
  try {
    std::rethrow_exception(p);
  } catch (const io::InputError& e) {
    py::dict a;
    a["kind"] = io::to_string(e.kind());
    a["file"] = e.file();
    a["where"] = e.where().to_string();
    a["problems"] = py::list();
    raise("InvalidInputError", e.what(), a);
  } catch (const io::SurfaceError& e) {
    py::dict a;
    a["kind"] = "surface";
    a["file"] = e.file();
    a["where"] = "";
    a["problems"] = problems_of(e.problems(), [](io::SurfaceProblemKind k) { return io::to_string(k); });
    raise("InvalidInputError", e.what(), a);
  } catch (const PlcError& e) {
    py::dict a;
    a["kind"] = "plc";
    a["file"] = "";
    a["where"] = "";
    a["problems"] = problems_of(e.problems(), [](PlcProblemKind k) { return to_string(k); });
    raise("InvalidInputError", e.what(), a);
  } catch (const NoCdtError& e) {
    py::dict a;
    a["witness"] = py::tuple(py::cast(e.witness()));
    raise("NoCdtError", no_cdt_message(e), a);
  } catch (const VertexRemovalError& e) {
    raise("VertexRemovalError", e.what());
  } catch (const OutputFailure& e) {
    raise("OutputError", e.what());
  } catch (const NotValid& e) {
    py::list failures;
    for (const auto& f : e.report.failures) failures.append(py::make_tuple(f.check, f.detail));
    py::dict a;
    a["failures"] = failures;
    raise("CheckError", e.what(), a);
  } catch (const CancelledError&) {
    // Normally turned into the exception that cancelled the run (running.h); a bare one is Ctrl-C's.
    PyErr_SetString(PyExc_KeyboardInterrupt, "cancelled");
  } catch (const std::bad_alloc&) {
    PyErr_SetString(PyExc_MemoryError, "out of memory");
  } catch (const std::filesystem::filesystem_error& e) {
    raise("InvalidInputError", e.path1().string() + ": " + e.code().message(),
          py::dict(py::arg("kind") = "Unreadable", py::arg("file") = e.path1().string(), py::arg("where") = "",
                   py::arg("problems") = py::list()));
  } catch (const Error& e) {
    PyErr_SetString(PyExc_RuntimeError, (std::string("internal error: ") + e.what()).c_str());
  }
  // Everything else (std::invalid_argument → ValueError, pybind11's own, other std exceptions →
  // RuntimeError) is pybind11's default translation, which catches whatever remains.
}

}  // namespace

void register_error_translator() { py::register_exception_translator(&translate); }

py::object removal_exception(std::exception_ptr error, int64_t vertex) {
  py::dict a;
  a["vertex"] = vertex;
  try {
    std::rethrow_exception(error);
  } catch (const NoCdtError& e) {
    a["witness"] = py::tuple(py::cast(e.witness()));
    return exception("NoCdtError", no_cdt_message(e), a);
  } catch (const VertexRemovalError& e) {
    return exception("VertexRemovalError", e.what(), a);
  }
}

}  // namespace sweepcdt::python
