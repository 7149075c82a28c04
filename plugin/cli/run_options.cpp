#include "run_options.h"

#include <stdexcept>

namespace sweepcdt::cli {

const char* to_string(SteinerMode mode) { return mode == SteinerMode::Auto ? "auto" : "none"; }
const char* to_string(FacetMode mode) { return mode == FacetMode::Coplanar ? "coplanar" : "triangles"; }

Options core_options(const RunOptions& options, CdtStatistics* statistics, std::function<bool(const Progress&)> progress) {
  Options o;
  o.algorithm = options.algorithm;
  o.steiner = options.steiner;
  o.facets = options.facets;
  o.remove_steiner_points = !options.keep_steiner;
  o.threads = options.core_threads;
  o.statistics = statistics;
  o.progress = std::move(progress);
  return o;
}

double parse_snap(const std::string& text) {
  std::size_t used = 0;
  double tolerance = 0;
  try {
    tolerance = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !(tolerance > 0 && tolerance <= io::kLargestSnap))
    throw UsageError("--snap needs a tolerance relative to the bounding-box diagonal, above 0 and at most 1e-3 (e.g. "
                     "--snap 1e-12), not '" + text + "'");
  return tolerance;
}

bool read_run_option(ArgReader& args, RunOptions& options) {
  if (read_facets_option(args, options.facets)) return true;
  std::string v;
  if (args.value("--algorithm", v)) {
    const std::optional<Algorithm> algorithm = algorithm_named(v);
    if (!algorithm) throw UsageError("--algorithm must be " + algorithm_choices() + ", not '" + v + "'");
    options.algorithm = *algorithm;
  } else if (args.value("--steiner", v)) {
    if (v == "auto") options.steiner = SteinerMode::Auto;
    else if (v == "none") options.steiner = SteinerMode::None;
    else throw UsageError("--steiner must be auto or none, not '" + v + "'");
  } else if (args.value("--snap", v)) {
    options.snap = parse_snap(v);
  } else if (args.flag("--keep-steiner-points")) {
    options.keep_steiner = true;
  } else if (args.flag("--check")) {
    options.check = true;
  } else if (args.value("--stats", v)) {
    options.stats_file = v;
  } else if (args.flag("--quiet") || args.flag("-q")) {
    options.quiet = true;
  } else {
    return false;
  }
  return true;
}

bool read_facets_option(ArgReader& args, FacetMode& facets) {
  std::string v;
  if (!args.value("--facets", v)) return false;
  if (v == "triangles") facets = FacetMode::Triangles;
  else if (v == "coplanar") facets = FacetMode::Coplanar;
  else throw UsageError("--facets must be triangles or coplanar, not '" + v + "'");
  return true;
}

}  // namespace sweepcdt::cli
