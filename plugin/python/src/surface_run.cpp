#include "surface_run.h"

#include <chrono>
#include <set>
#include <utility>

#include "arrays.h"
#include "errors.h"
#include "sweepcdt/io/surface_arrays.h"

namespace sweepcdt::python {
namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// kNone (no point / no triangle) as -1, numpy's usual "none" for ids.
std::vector<int64_t> with_minus_one(const std::vector<uint32_t>& ids) {
  std::vector<int64_t> out(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) out[i] = ids[i] == kNone ? -1 : static_cast<int64_t>(ids[i]);
  return out;
}

}  // namespace

SurfaceRun run_surface(const io::Soup& soup, const RunKeywords& k, Watch& watch) {
  SurfaceRun run;
  const auto start = std::chrono::steady_clock::now();
  run.input_points = soup.num_points();
  run.input_triangles = soup.num_triangles();
  watch.phase("checking surface");
  const Plc<3> plc = io::plc_of_soup(soup, k.snap, &run.snap, &run.point_ids);
  run.seconds_surface = since(start);

  Options options;
  options.algorithm = k.algorithm;
  options.steiner = k.steiner;
  options.facets = k.facets;
  options.statistics = &run.cdt;
  options.progress = watch.core_callback();
  Plc<3> triangulated;
  Triangulation<3> tri = cdt(plc, options, &triangulated);

  if (k.check) {
    watch.phase("validating");
    const auto t = std::chrono::steady_clock::now();
    ValidationReport report = validate_triangulated(tri, triangulated);
    run.seconds_validate = since(t);
    if (!report.ok())
      throw NotValid(soup.file + ": check: the computed triangulation is not a valid CDT: " + report.summary(), std::move(report));
    run.validated = true;
  }
  watch.phase("volume mesh");
  run.mesh = io::volume_mesh_of(std::move(tri), triangulated);
  run.seconds_total = since(start);
  return run;
}

py::dict result_dict(const SurfaceRun& run, const RunKeywords& k) {
  const io::VolumeMesh& m = run.mesh;
  py::dict r;
  r["points"] = to_numpy<double>(m.points, 3);
  // Like every file format (io/src/volume_mesh_formats.h): (a, b, d, c), so that det[b-a, c-a, d-a] > 0
  // (VTK, meshio, Gmsh order) rather than sweepcdt's orient3d convention, its negative.
  std::vector<uint32_t> tets = m.tetrahedra;
  for (std::size_t t = 0; t + 3 < tets.size(); t += 4) std::swap(tets[t + 2], tets[t + 3]);
  r["tetrahedra"] = to_numpy<int64_t>(tets, 4);
  r["regions"] = to_numpy<int32_t>(m.regions, 0);
  r["triangles"] = to_numpy<int64_t>(m.boundary, 3);
  r["triangle_ids"] = to_numpy<int64_t>(m.boundary_tags, 0);
  r["num_input_points"] = m.num_input_points;
  // Per Steiner point (points num_input_points..): the input triangle it lies on, -1 if inside.
  std::vector<uint32_t> steiner_on;
  if (!m.on_triangle.empty()) steiner_on.assign(m.on_triangle.begin() + m.num_input_points, m.on_triangle.end());
  else steiner_on.assign(m.num_points() - m.num_input_points, kNone);
  r["steiner_triangles"] = to_numpy<int64_t>(with_minus_one(steiner_on), 0);
  r["point_ids"] = to_numpy<int64_t>(with_minus_one(run.point_ids), 0);

  py::dict s;
  s["algorithm"] = to_string(run.cdt.algorithm);
  s["steiner"] = name_of(k.steiner);
  s["facets"] = name_of(k.facets);
  s["input_points"] = run.input_points;
  s["input_triangles"] = run.input_triangles;
  s["points"] = m.num_points();
  s["steiner_points"] = run.cdt.steiner_points;
  s["steiner_points_removed"] = run.cdt.steiner_points_removed;
  s["steiner_deletions_tried"] = run.cdt.steiner_deletions_tried;
  s["steiner_retries_skipped"] = run.cdt.steiner_retries_skipped;
  s["steiner_refused_early"] = run.cdt.steiner_refused_early;
  s["tetrahedra"] = m.num_tetrahedra();
  s["boundary_triangles"] = m.num_boundary();
  s["regions"] = std::set<int32_t>(m.regions.begin(), m.regions.end()).size();
  s["steiner_rounds"] = run.cdt.steiner_rounds;
  s["steiner_attempts"] = run.cdt.steiner_attempts;
  s["facets_triangulated"] = run.cdt.facets;
  s["facet_flips"] = run.cdt.facet_flips;
  s["queue_pushes"] = run.cdt.queue_pushes;
  s["queue_pops"] = run.cdt.queue_pops;
  s["stale_pops"] = run.cdt.stale_pops;
  s["drop_moves"] = run.cdt.drop_moves;
  s["missing_constraints"] = run.cdt.missing_constraints;
  s["cavity_tetrahedra"] = run.cdt.cavity_tetrahedra;
  s["perturbation_orders"] = run.cdt.perturbation_orders;
  s["perturbation_order"] = run.cdt.perturbation_order;
  s["snapped_points"] = run.snap.points_moved;
  s["snap_largest_move"] = run.snap.largest_move;
  s["checked"] = run.validated;
  s["check_recorded"] = run.cdt.check_recorded;                            // the import's intersection check reused
  s["tetrahedralization_recorded"] = run.cdt.tetrahedralization_recorded;  // and its tetrahedralization
  s["seconds_surface"] = run.seconds_surface;
  s["seconds_check"] = run.cdt.seconds_check;
  s["seconds_setup"] = run.cdt.seconds_setup;
  s["seconds_build"] = run.cdt.seconds_build;
  s["seconds_finish"] = run.cdt.seconds_finish;
  s["seconds_validate"] = run.seconds_validate;
  s["seconds_total"] = run.seconds_total;
  r["stats"] = s;
  return r;
}

}  // namespace sweepcdt::python
