// The Python keywords of a run (algorithm="sweep-sphere", steiner=..., facets=..., snap=...) as core
// Options, spelled as the converter spells its options; defaults are the converter's own (its
// RunOptions), so the module cannot drift from `sweepcdt mesh`.
#pragma once
#include <optional>
#include <string>

#include "sweepcdt/cdt.h"

namespace sweepcdt::python {

struct RunKeywords {
  Algorithm algorithm;
  SteinerMode steiner;
  FacetMode facets;
  double snap = 0;  // 0: the input as given
  bool check = false;
};

// The converter's defaults (`sweepcdt mesh` with no options).
RunKeywords converter_defaults();

// Parses the keywords (nullopt = default); throws std::invalid_argument (ValueError) naming the keyword.
RunKeywords run_keywords(const std::optional<std::string>& algorithm, const std::optional<std::string>& steiner,
                         const std::optional<std::string>& facets, std::optional<double> snap, bool check);

const char* name_of(SteinerMode mode);
const char* name_of(FacetMode mode);

}  // namespace sweepcdt::python
