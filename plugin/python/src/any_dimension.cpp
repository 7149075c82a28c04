#include "any_dimension.h"

#include <chrono>
#include <utility>

#include "arrays.h"
#include "errors.h"
#include "options.h"
#include "running.h"
#include "sweepcdt/cdt.h"

namespace sweepcdt::python {
namespace {

ExteriorSide exterior_side(int64_t v, std::size_t j) {
  if (v == 0) return ExteriorSide::None;
  if (v == 1) return ExteriorSide::Positive;
  if (v == -1) return ExteriorSide::Negative;
  throw py::value_error("exterior[" + std::to_string(j) + "] must be -1 (negative side exterior), 0 (none) or "
                        "1 (positive side exterior), not " + std::to_string(v));
}

template <int D>
py::dict run(std::vector<double> points, const std::vector<int64_t>& simplices, const std::vector<int64_t>& exterior,
             const std::vector<int64_t>& tags, const RunKeywords& k, Watch& watch) {
  Plc<D> plc;
  plc.points = std::move(points);
  const std::size_t n = plc.num_points();
  plc.simplices.reserve(simplices.size());
  for (std::size_t c = 0; c < simplices.size(); ++c) {
    // Out-of-range ids are core's to report (PlcError names the simplex); only what does not fit
    // uint32 is refused here, so that it is not wrapped into a valid id.
    if (simplices[c] < 0 || simplices[c] >= static_cast<int64_t>(kNone))
      throw py::value_error("simplices[" + std::to_string(c / D) + "]: point id " + std::to_string(simplices[c]) +
                            " is not in [0, " + std::to_string(n) + ")");
    plc.simplices.push_back(static_cast<uint32_t>(simplices[c]));
  }
  for (std::size_t j = 0; j < exterior.size(); ++j) plc.exterior.push_back(exterior_side(exterior[j], j));
  for (int64_t t : tags) plc.tags.push_back(static_cast<uint32_t>(t));

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
  // core's orient (Shewchuk's) is sign det[p_0 - p_D; ...; p_{D-1} - p_D], which is (-1)^D times the
  // usual det[p_1 - p_0; ...; p_D - p_0]: for odd D, swap the last two vertices so that every
  // simplex has positive volume in the usual sense (as tetrahedralize() and the file formats do).
  std::vector<uint32_t> oriented = tri.simplices;
  if (D % 2 == 1)
    for (std::size_t t = 0; t + D < oriented.size(); t += D + 1) std::swap(oriented[t + D - 1], oriented[t + D]);
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
                           const std::optional<std::string>& steiner, bool check, py::object progress) {
  int d = 0;
  std::vector<double> p = real_matrix(points, "points", -1, &d);
  if (d < 2 || d > 5) throw py::value_error("points must have 2 to 5 columns (the dimension), not " + std::to_string(d));
  const std::vector<int64_t> s = index_matrix(simplices, "simplices", d);
  const std::size_t m = s.size() / d;
  const std::vector<int64_t> e = exterior.is_none() ? std::vector<int64_t>{} : index_vector(exterior, "exterior", m);
  const std::vector<int64_t> t = tags.is_none() ? std::vector<int64_t>{} : index_vector(tags, "tags", m);
  for (std::size_t j = 0; j < t.size(); ++j)
    if (t[j] < 0 || t[j] >= static_cast<int64_t>(kNone)) throw py::value_error("tags[" + std::to_string(j) + "] must be in [0, 2^32 - 1)");
  // The PLC is taken as given (the converter's `cdt` command): no Steiner points unless asked.
  RunKeywords k = run_keywords(algorithm, steiner ? steiner : std::optional<std::string>("none"), std::nullopt, std::nullopt, check);
  if (k.steiner == SteinerMode::Auto && d != 3) throw py::value_error("steiner='auto' is implemented for D = 3 only");
  Watch watch(std::move(progress));
  try {
    switch (d) {
      case 2: return run<2>(std::move(p), s, e, t, k, watch);
      case 3: return run<3>(std::move(p), s, e, t, k, watch);
      case 4: return run<4>(std::move(p), s, e, t, k, watch);
      default: return run<5>(std::move(p), s, e, t, k, watch);
    }
  } catch (const CancelledError&) {
    watch.rethrow();
  }
}

}  // namespace sweepcdt::python
