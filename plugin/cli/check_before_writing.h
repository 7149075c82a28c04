// --check, shared by the commands that compute a CDT (`mesh`, `cdt`): validate() the result once
// more, against the PLC actually triangulated, before anything is written.
#pragma once
#include <chrono>
#include <string>

#include "exit_codes.h"
#include "file_result.h"
#include "progress.h"
#include "sweepcdt/cdt.h"

namespace sweepcdt::cli {

inline double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// True when valid (r.validated set); otherwise fills r's code (kNotValid), message and details.
template <int D>
bool check_before_writing(const Triangulation<D>& tri, const Plc<D>& triangulated, FileProgress& progress, FileResult& r) {
  progress.phase("validating");
  const auto start = std::chrono::steady_clock::now();
  const ValidationReport report = validate_triangulated(tri, triangulated);
  r.seconds_validate = since(start);
  if (report.ok()) {
    r.validated = true;
    return true;
  }
  r.code = kNotValid;
  r.message = r.input + ": --check: the computed triangulation is not a valid CDT (" + std::to_string(report.failures.size()) +
              " problems shown); nothing written";
  for (const auto& f : report.failures) r.details.push_back(r.input + ": " + f.check + ": " + f.detail);
  return false;
}

}  // namespace sweepcdt::cli
