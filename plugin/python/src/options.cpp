#include "options.h"

#include <cmath>
#include <stdexcept>

#include "sweepcdt/cdt.h"      // mesh_defaults(): the converter's defaults
#include "sweepcdt/io/snap.h"  // io::kLargestSnap: the converter's bound

namespace sweepcdt::python {

RunKeywords converter_defaults() {
  const Options defaults = mesh_defaults();
  return {defaults.algorithm, defaults.steiner, defaults.facets, 0.0, false};
}

const char* name_of(SteinerMode mode) { return mode == SteinerMode::Auto ? "auto" : "none"; }
const char* name_of(FacetMode mode) { return mode == FacetMode::Coplanar ? "coplanar" : "triangles"; }

RunKeywords run_keywords(const std::optional<std::string>& algorithm, const std::optional<std::string>& steiner,
                         const std::optional<std::string>& facets, std::optional<double> snap, bool check) {
  RunKeywords k = converter_defaults();
  if (algorithm) {
    const std::optional<Algorithm> named = algorithm_named(*algorithm);
    if (!named) throw std::invalid_argument("algorithm must be " + algorithm_choices() + ", not '" + *algorithm + "'");
    k.algorithm = *named;
  }
  if (steiner) {
    if (*steiner == "auto") k.steiner = SteinerMode::Auto;
    else if (*steiner == "none") k.steiner = SteinerMode::None;
    else throw std::invalid_argument("steiner must be 'auto' or 'none', not '" + *steiner + "'");
  }
  if (facets) {
    if (*facets == "triangles") k.facets = FacetMode::Triangles;
    else if (*facets == "coplanar") k.facets = FacetMode::Coplanar;
    else throw std::invalid_argument("facets must be 'triangles' or 'coplanar', not '" + *facets + "'");
  }
  if (snap) {
    // The converter's bound: snapping repairs rounding noise, not modelling error.
    if (!(*snap > 0 && *snap <= io::kLargestSnap))
      throw std::invalid_argument("snap must be a tolerance relative to the bounding-box diagonal, above 0 and at most " +
                                  std::to_string(io::kLargestSnap) + " (e.g. 1e-12), or None");
    k.snap = *snap;
  }
  k.check = check;
  return k;
}

}  // namespace sweepcdt::python
