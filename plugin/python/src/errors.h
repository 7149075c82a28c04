// Every C++ exception becomes a Python exception (nothing may terminate the interpreter FreeCAD
// runs in), with the meaning of the converter's exit codes (plugin/cli/errors.cpp):
//
//   io::InputError, io::SurfaceError, PlcError  → sweepcdt.InvalidInputError (exit 3; a ValueError)
//   NoCdtError                                  → sweepcdt.NoCdtError (exit 4; .witness)
//   VertexRemovalError                          → sweepcdt.VertexRemovalError (a ValueError)
//   OutputFailure (below)                       → sweepcdt.OutputError (exit 5; an OSError)
//   NotValid (below)                            → sweepcdt.CheckError (exit 6; .failures)
//   std::bad_alloc                              → MemoryError
//   anything else                               → RuntimeError "internal error: ..." (exit 1)
// The exception classes live in sweepcdt/errors.py.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include <exception>

#include "sweepcdt/validate.h"

namespace sweepcdt::python {

// An output file could not be written (writers report it as io::InputError Unreadable).
class OutputFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// check=True found the result invalid.
class NotValid : public std::runtime_error {
 public:
  NotValid(const std::string& what, ValidationReport report) : std::runtime_error(what), report(std::move(report)) {}
  ValidationReport report;
};

void register_error_translator();

// The Python exception object (not raised) for a refused vertex deletion: NoCdtError or
// VertexRemovalError, with .vertex set (EditableCdt.remove_vertices reports them without raising).
// Rethrows anything else.
pybind11::object removal_exception(std::exception_ptr error, int64_t vertex);

}  // namespace sweepcdt::python
