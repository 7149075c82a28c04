// --check, shared by the commands that compute a CDT, before anything is written: `mesh` runs the
// library's verification (sweepcdt/io/verify_mesh.h, what `sweepcdt check` runs) on the volume mesh
// against the input surface; `cdt` (any dimension, any PLC) validate()s the result once more against
// the PLC actually triangulated.
#pragma once
#include <chrono>
#include <string>

#include "exit_codes.h"
#include "file_result.h"
#include "progress.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/verify_mesh.h"

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

// The same for a surface's volume mesh (`mesh`): is it exactly the CDT of `input` under `facets`?
inline bool verify_before_writing(const Plc<3>& input, const io::VolumeMesh& mesh, FacetMode facets, FileProgress& progress, FileResult& r) {
  progress.phase("validating");
  const auto start = std::chrono::steady_clock::now();
  const MeshVerification v = io::verify_mesh(input, mesh, facets);
  r.seconds_validate = since(start);
  if (v.ok()) {
    r.validated = true;
    return true;
  }
  r.code = kNotValid;
  r.message = r.input + ": --check: the computed mesh is not the CDT of the input (" + std::to_string(v.total_problems) +
              " problems); nothing written";
  for (const auto& p : v.problems) r.details.push_back(r.input + ": " + p);
  return false;
}

}  // namespace sweepcdt::cli
