#include "convert_surface.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <set>

#include "check_before_writing.h"
#include "errors.h"
#include "sweepcdt/io/read.h"
#include "sweepcdt/io/to_plc.h"

namespace sweepcdt::cli {
namespace {

void fail(FileResult& r, Failure f) {
  r.code = f.code;
  r.message = std::move(f.message);
  r.details = std::move(f.details);
}

// The files write_volume_mesh() made for `target` (TetGen: three beside each other).
void remove_mesh_files(const MeshTarget& target) {
  std::error_code ec;
  for (const auto& file : io::volume_mesh_files(target.file, target.format)) std::filesystem::remove(file, ec);
}

// The tolerance the hint below suggests: far above rounding noise, far below modelling detail.
constexpr double kSuggestedSnap = 1e-12;

// Why an input without a CDT may only look that way, or why it needed many Steiner points: faces
// flat by design but stored with rounding noise (sweepcdt/io/snap.h). Empty unless --snap would make
// some faces exactly flat (or when the input cannot be re-read).
std::string snap_hint(const std::string& input, FacetMode facets) {
  try {
    io::SnapReport report;
    io::snap_coordinates(io::weld(io::read_soup(input)), kSuggestedSnap, report);
    if (report.edges_flattened == 0) return {};
    char moved[32];
    std::snprintf(moved, sizeof moved, "%.2g", report.largest_move);
    return "hint: moving " + std::to_string(report.points_moved) + " vertices by up to " + moved +
           " (CAD rounding noise?) would make the triangles at " + std::to_string(report.edges_flattened) +
           " edges exactly coplanar: `" + (facets == FacetMode::Coplanar ? "--snap 1e-12" : "--snap 1e-12 --facets coplanar") +
           "` makes faces that are flat by design exactly flat, each one facet";
  } catch (...) {
    return {};
  }
}

}  // namespace

FileResult convert_surface(const std::string& input, const std::vector<MeshTarget>& targets, const RunOptions& options,
                           FileProgress& progress) {
  FileResult r;
  r.input = input;
  for (const auto& t : targets) r.outputs.push_back({t.file, io::to_string(t.format)});
  std::size_t written = 0;
  const auto start = std::chrono::steady_clock::now();
  bool writing = false;
  try {
    throw_if_interrupted();
    progress.phase("reading");
    const Plc<3> plc = io::import_plc(input, options.snap, &r.snap);
    r.seconds_read = since(start);
    r.input_points = plc.num_points();
    r.input_simplices = plc.num_simplices();

    const Options cdt_options = core_options(options, &r.cdt, progress.callback());
    Plc<3> triangulated;
    Triangulation<3> tri = cdt(plc, cdt_options, &triangulated);
    r.computed = true;
    r.simplices = tri.num_simplices();

    const io::VolumeMesh mesh = counted_volume_mesh(std::move(tri), triangulated, r);
    if (options.check && !verify_before_writing(plc, mesh, cdt_options.facets, progress, r)) {
      r.seconds_total = since(start);
      return r;
    }

    // Last chance to stop: once the writer runs, the file is completed (it is atomic either way).
    throw_if_interrupted();
    progress.phase("writing");
    writing = true;
    const auto t = std::chrono::steady_clock::now();
    for (; written < targets.size(); ++written) io::write_volume_mesh(targets[written].file, mesh, targets[written].format);
    r.seconds_write = since(t);
    for (const MeshTarget& target : targets)
      if (target.format == io::MeshFormat::Abaqus) warn_if_rounded(target.file, mesh, r);
    // More Steiner points than input vertices: rounding noise on flat faces is the usual cause.
    if (options.snap == 0 && r.cdt.steiner_points > r.input_points)
      if (std::string hint = snap_hint(input, options.facets); !hint.empty()) r.details.push_back(hint + " (and needs fewer Steiner points)");
  } catch (...) {
    fail(r, describe_current_exception(input, writing));
    if (r.code == kNoCdt && options.snap == 0)
      if (std::string hint = snap_hint(input, options.facets); !hint.empty()) r.details.push_back(std::move(hint));
    for (std::size_t k = 0; k < written; ++k) remove_mesh_files(targets[k]);
  }
  r.seconds_total = since(start);
  return r;
}

io::VolumeMesh counted_volume_mesh(Triangulation<3> tri, const Plc<3>& triangulated, FileResult& r) {
  io::VolumeMesh mesh = io::volume_mesh_of(std::move(tri), triangulated);
  r.boundary_triangles = mesh.num_boundary();
  r.regions = std::set<int32_t>(mesh.regions.begin(), mesh.regions.end()).size();
  return mesh;
}

// Abaqus .inp holds coordinates in CalculiX's 20-character fields, so io rounds the ones that do not
// fit: the file is then not exactly the CDT. Reading it back is cheap next to the CDT, and tells.
void warn_if_rounded(const std::string& file, const io::VolumeMesh& mesh, FileResult& r) {
  const io::VolumeMesh back = io::read_volume_mesh(file);
  std::size_t rounded = 0;
  double largest = 0;
  for (std::size_t k = 0; k < mesh.points.size() && k < back.points.size(); ++k)
    if (back.points[k] != mesh.points[k]) {
      ++rounded;
      largest = std::max(largest, std::abs(back.points[k] - mesh.points[k]));
    }
  if (rounded == 0) return;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", largest);
  r.warnings.push_back(file + ": " + std::to_string(rounded) + " coordinates rounded to fit CalculiX's 20-character fields (by up to " + buf +
                       "): the file is not exactly the CDT; use .mesh, .vtu, .msh or .node for exact coordinates");
}

std::string summary_of(const FileResult& r) {
  char buf[96];
  std::snprintf(buf, sizeof buf, " (%s, %.2f s)", to_string(r.cdt.algorithm), r.seconds_total);
  const char* what = r.dimension == 2 ? " triangles" : r.dimension == 3 ? " tetrahedra" : " simplices";
  std::string s = std::to_string(r.simplices) + what;
  if (r.dimension == 3) {
    s += ", " + std::to_string(r.cdt.steiner_points) + " Steiner points";
    if (r.cdt.steiner_points_removed)  // issue 17: refinement's points that a CDT can do without
      s += " (" + std::to_string(r.cdt.steiner_points + r.cdt.steiner_points_removed) + " added, " +
           std::to_string(r.cdt.steiner_points_removed) + " deleted again)";
  }
  // Paper §6: the vertex-id perturbation left the PLC without a CDT; say which order gave one.
  if (r.snap.points_moved > 0) {
    char moved[64];
    std::snprintf(moved, sizeof moved, "%.3g", r.snap.largest_move);
    s += ", " + std::to_string(r.snap.points_moved) + " points snapped (by up to " + moved + ")";
  }
  if (r.cdt.perturbation_order > 0)
    s += ", perturbation order " + std::to_string(r.cdt.perturbation_order) + " (" + perturbation_order_name(static_cast<int>(r.cdt.perturbation_order)) + ")";
  if (r.validated) s += ", checked";
  return s + buf;
}

}  // namespace sweepcdt::cli
