#include "job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "sweepcdt/cdt.h"
#include "sweepcdt/io/cut_away.h"
#include "sweepcdt/io/error.h"
#include "sweepcdt/io/problem_triangles.h"
#include "sweepcdt/io/snap.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/io/tetrahedron_quality.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::meshlab {
namespace {

constexpr std::size_t kDetailsShown = 10;

// A failure the job itself found (not a library exception): its message is the result's error.
struct JobError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string format_double(const char* fmt, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

double parse_snap(const std::string& text) {
  std::size_t used = 0;
  double tolerance = -1;
  try {
    tolerance = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !(tolerance >= 0 && tolerance <= io::kLargestSnap))
    throw JobError("snap tolerance must be 0 (no snapping) or a number above 0 and at most 1e-3 relative to the bounding-box diagonal "
                   "(e.g. 1e-12), not '" + text + "'");
  return tolerance;
}

// The library's multi-line messages: the first line is the error, the rest are problems.
void split_lines(const std::string& text, const std::string& prefix, JobResult& r) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (r.error.empty()) r.error = prefix + line;
    else if (r.details.size() < kDetailsShown) r.details.push_back(line.substr(std::min(line.find_first_not_of(' '), line.size())));
  }
}

std::string ids_text(const std::vector<uint32_t>& ids) {
  std::string s;
  for (uint32_t id : ids) s += (s.empty() ? "" : " ") + std::to_string(id);
  return s;
}

// The layer's triangles that keep it from bounding a volume: error, details and selection.
void describe_surface_problems(const std::string& name, const io::Surface& surface, const io::SurfaceReport& report, JobResult& r) {
  // In SurfaceProblemKind's order.
  static const char* const kWhat[io::kSurfaceProblemKinds] = {
      "degenerate triangles", "duplicate triangles", "boundary edges (the surface is open)", "non-manifold edges",
      "non-manifold (pinched) vertices", "non-orientable shells", "self-intersecting triangle pairs"};
  std::string kinds;
  for (int k = 0; k < io::kSurfaceProblemKinds; ++k)
    if (report.counts[k]) kinds += (kinds.empty() ? "" : ", ") + std::to_string(report.counts[k]) + " " + kWhat[k];
  r.select = io::problem_triangles(surface, report);
  r.error = name + ": the layer does not bound a volume: " + kinds + "; " + std::to_string(r.select.size()) + " faces selected";
  for (const io::SurfaceProblem& p : report.problems) {
    if (r.details.size() == kDetailsShown) break;
    r.details.push_back(p.message);
  }
}

void fill_cut_away(const io::VolumeMesh& mesh, const JobInput& in, JobResult& r) {
  const io::CutAway cut = io::cut_away(mesh, in.cut_axis, in.cut_fraction);
  std::vector<uint32_t> new_id(mesh.num_points(), UINT32_MAX);
  for (uint32_t v : cut.triangles) {
    if (new_id[v] != UINT32_MAX) continue;
    new_id[v] = static_cast<uint32_t>(r.points.size() / 3);
    r.points.insert(r.points.end(), mesh.points.begin() + 3 * std::size_t{v}, mesh.points.begin() + 3 * std::size_t{v} + 3);
  }
  for (uint32_t v : cut.triangles) r.triangles.push_back(new_id[v]);
  for (std::size_t t = 0; t < cut.num_triangles(); ++t) {
    r.quality.push_back(io::radius_ratio(mesh, cut.tetrahedron[t]));
    r.region.push_back(mesh.regions.empty() ? 0 : mesh.regions[cut.tetrahedron[t]]);
  }
  r.on_cut = cut.on_cut;
  const char* axis = in.cut_axis == 0 ? "x" : in.cut_axis == 1 ? "y" : "z";
  r.log.push_back("cut-away layer: the " + std::to_string(cut.kept_tetrahedra) + " of " + std::to_string(mesh.num_tetrahedra()) +
                  " tetrahedra with centroid at " + axis + " <= " + format_double("%.6g", cut.position) + ", " +
                  std::to_string(cut.num_triangles()) + " triangles");
}

}  // namespace

Choices choices() {
  Choices c;
  for (const Algorithm a : kAlgorithms) c.algorithms.push_back(to_string(a));
  c.steiner = {"auto", "none"};
  c.facets = {"triangles", "coplanar"};
  c.axes = {"x", "y", "z"};
  c.colourings = {"element quality", "region"};
  // The converter's defaults (mesh_defaults(): Steiner points where needed, coplanar facets): a
  // MeshLab layer is a real surface, which most often has no CDT as given.
  const Options defaults = mesh_defaults();
  c.default_algorithm = static_cast<int>(std::find(std::begin(kAlgorithms), std::end(kAlgorithms), defaults.algorithm) - std::begin(kAlgorithms));
  c.default_steiner = defaults.steiner == SteinerMode::Auto ? 0 : 1;
  c.default_facets = defaults.facets == FacetMode::Coplanar ? 1 : 0;
  return c;
}

JobResult run_job(const JobInput& in) {
  JobResult r;
  const auto start = std::chrono::steady_clock::now();
  const auto progress = [&](int percent, const char* phase) {
    if (in.progress) in.progress(percent, phase);
  };
  io::Surface surface;
  try {
    if (in.output.empty()) throw JobError("no output file given");
    const std::optional<io::MeshFormat> format = io::mesh_format_of(in.output);
    if (!format) throw JobError(in.output + ": unknown volume mesh extension (use .mesh, .vtu, .msh, .node or .inp)");
    if (in.algorithm < 0 || in.algorithm >= static_cast<int>(std::size(kAlgorithms)) || in.steiner < 0 || in.steiner > 1 || in.facets < 0 || in.facets > 1 ||
        in.cut_axis < 0 || in.cut_axis > 2 || !(in.cut_fraction >= 0 && in.cut_fraction <= 1))
      throw JobError("a parameter is out of range");
    const double snap = parse_snap(in.snap);

    progress(0, "checking the surface");
    // MeshLab layers can hold anything; the library's file readers refuse non-finite coordinates,
    // and so does this (every later test assumes finite numbers).
    std::vector<uint32_t> bad_points;
    for (std::size_t i = 0; i < in.points.size(); ++i)
      if (!std::isfinite(in.points[i]) && (bad_points.empty() || bad_points.back() != i / 3)) bad_points.push_back(static_cast<uint32_t>(i / 3));
    if (!bad_points.empty()) {
      for (uint32_t t = 0; t < in.triangles.size() / 3; ++t)
        for (int k = 0; k < 3; ++k)
          if (std::binary_search(bad_points.begin(), bad_points.end(), in.triangles[3 * t + k])) {
            r.select.push_back(t);
            break;
          }
      r.error = in.name + ": vertex " + std::to_string(bad_points[0]) + " has a non-finite coordinate (" +
                std::to_string(bad_points.size()) + " such vertices); " + std::to_string(r.select.size()) + " faces selected";
      return r;
    }
    io::Soup soup;
    soup.file = in.name;
    soup.points = in.points;
    soup.triangles = in.triangles;
    surface = io::weld(soup);
    io::SnapReport snapped;
    if (snap > 0) surface = io::snap_coordinates(surface, snap, snapped);
    const io::SurfaceReport report = io::inspect(surface, SIZE_MAX, /*before_cdt=*/true);
    if (!report.valid()) {
      describe_surface_problems(in.name, surface, report, r);
      return r;
    }
    const Plc<3> plc = io::to_plc(surface, report);

    Options options;
    options.algorithm = kAlgorithms[in.algorithm];
    options.steiner = in.steiner == 0 ? SteinerMode::Auto : SteinerMode::None;
    options.facets = in.facets == 1 ? FacetMode::Coplanar : FacetMode::Triangles;
    CdtStatistics stats;
    options.statistics = &stats;
    options.progress = [&](const Progress& p) {
      const int percent = p.total ? 5 + static_cast<int>(80.0 * std::min(p.done, p.total) / p.total) : 5;
      progress(percent, p.phase);
      return true;
    };
    Plc<3> triangulated;
    Triangulation<3> tri = cdt(plc, options, &triangulated);
    if (in.verify) {
      progress(85, "verifying");
      const ValidationReport v = validate_triangulated(tri, triangulated);
      if (!v.ok()) {
        split_lines(v.summary(), in.name + ": the computed triangulation is not a valid CDT: ", r);
        return r;
      }
    }
    progress(90, "writing");
    const io::VolumeMesh mesh = io::volume_mesh_of(std::move(tri), triangulated);
    io::write_volume_mesh(in.output, mesh, *format);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::string summary = in.name + ": " + std::to_string(surface.num_triangles()) + " triangles, " + std::to_string(surface.num_points()) +
                          " vertices -> " + std::to_string(mesh.num_tetrahedra()) + " tetrahedra, " + std::to_string(stats.steiner_points) +
                          " Steiner points";
    if (snapped.points_moved > 0)
      summary += ", " + std::to_string(snapped.points_moved) + " points snapped (by up to " + format_double("%.3g", snapped.largest_move) + ")";
    if (stats.perturbation_order > 0) summary += ", perturbation order " + std::to_string(stats.perturbation_order);
    if (in.verify) summary += ", verified";
    summary += " (" + std::string(to_string(stats.algorithm)) + ", " + format_double("%.2f", seconds) + " s)";
    r.log.push_back(summary);
    r.log.push_back("wrote " + in.output + " (" + io::to_string(*format) + ")");

    progress(95, "cut-away layer");
    fill_cut_away(mesh, in, r);
    progress(100, "done");
    r.ok = true;
  } catch (const JobError& e) {
    r.error = e.what();
  } catch (const io::InputError& e) {
    r.error = e.what();  // while writing: the output cannot be written
  } catch (const io::SurfaceError& e) {
    split_lines(e.what(), "", r);
  } catch (const PlcError& e) {
    split_lines(e.what(), in.name + ": ", r);
  } catch (const NoCdtError& e) {
    r.error = in.name + ": " + e.what();
    if (!e.witness().empty()) {
      r.error += " (witness vertices " + ids_text(e.witness()) + ")";
      r.select = io::triangles_at_vertices(surface, e.witness());
      r.details.push_back(std::to_string(r.select.size()) + " faces at the witness vertices selected");
    }
    if (in.steiner == 1) r.details.push_back("Steiner mode 'none' keeps the surface as given: try 'auto'");
  } catch (const std::bad_alloc&) {
    r.error = in.name + ": out of memory";
  } catch (const std::exception& e) {
    r.error = in.name + ": internal error: " + e.what();
  } catch (...) {
    r.error = in.name + ": internal error: unknown exception";
  }
  return r;
}

}  // namespace sweepcdt::meshlab
