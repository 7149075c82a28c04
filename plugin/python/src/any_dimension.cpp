#include "any_dimension.h"

#include <chrono>
#include <utility>

#include "arrays.h"
#include "errors.h"
#include "options.h"
#include "plc_arrays.h"
#include "running.h"
#include "sweepcdt/cdt.h"

namespace sweepcdt::python {
namespace {

template <int D>
py::dict run(PlcArrays arrays, const RunKeywords& k, Watch& watch) {
  const Plc<D> plc = plc_of<D>(std::move(arrays));
  CdtStatistics stats;
  Options options;
  options.algorithm = k.algorithm;
  options.steiner = k.steiner;
  options.facets = k.facets;
  options.statistics = &stats;
  options.progress = watch.core_callback();
  Triangulation<D> tri;
  bool validated = false;
  {
    py::gil_scoped_release release;
    Plc<D> triangulated;
    tri = cdt(plc, options, &triangulated);
    if (k.check) {
      watch.phase("validating");
      ValidationReport report = validate_triangulated(tri, triangulated);
      if (!report.ok()) throw NotValid("check: the computed triangulation is not a valid CDT: " + report.summary(), std::move(report));
      validated = true;
    }
  }
  py::dict r;
  r["dimension"] = D;
  r["points"] = to_numpy<double>(tri.points, D);
  // Every simplex with positive volume in the usual sense, as tetrahedralize() and the file formats have it.
  std::vector<uint32_t> oriented = tri.simplices;
  swap_orientation_convention<D>(oriented);
  r["simplices"] = to_numpy<int64_t>(oriented, D + 1);
  r["regions"] = to_numpy<int32_t>(tri.regions, 0);
  r["num_input_points"] = tri.num_input_points;
  std::vector<int64_t> on(tri.steiner_on.size());
  for (std::size_t i = 0; i < on.size(); ++i) on[i] = tri.steiner_on[i] == kNone ? -1 : static_cast<int64_t>(tri.steiner_on[i]);
  r["steiner_simplices"] = to_numpy<int64_t>(on, 0);
  py::dict s;
  s["algorithm"] = to_string(stats.algorithm);
  s["simplices"] = stats.simplices;
  s["steiner_points"] = stats.steiner_points;
  s["perturbation_orders"] = stats.perturbation_orders;
  s["perturbation_order"] = stats.perturbation_order;
  s["checked"] = validated;
  s["seconds_check"] = stats.seconds_check;
  s["seconds_setup"] = stats.seconds_setup;
  s["seconds_build"] = stats.seconds_build;
  s["seconds_finish"] = stats.seconds_finish;
  r["stats"] = s;
  return r;
}

}  // namespace

py::dict cdt_any_dimension(const py::handle& points, const py::handle& simplices, const py::handle& exterior,
                           const py::handle& tags, const std::optional<std::string>& algorithm,
                           const std::optional<std::string>& steiner, const std::optional<std::string>& facets,
                           bool check, py::object progress) {
  PlcArrays arrays = plc_arrays(points, simplices, exterior, tags);
  const int d = arrays.dimension;
  // The PLC is taken as given (the converter's `cdt` command): no Steiner points unless asked.
  RunKeywords k = run_keywords(algorithm, steiner ? steiner : std::optional<std::string>("none"), facets, std::nullopt, check);
  if (k.steiner == SteinerMode::Auto && d != 3) throw py::value_error("steiner='auto' is implemented for D = 3 only");
  Watch watch(std::move(progress));
  try {
    switch (d) {
      case 2: return run<2>(std::move(arrays), k, watch);
      case 3: return run<3>(std::move(arrays), k, watch);
      case 4: return run<4>(std::move(arrays), k, watch);
      default: return run<5>(std::move(arrays), k, watch);
    }
  } catch (const CancelledError&) {
    watch.rethrow();
  }
}

}  // namespace sweepcdt::python
