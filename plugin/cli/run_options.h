// Options shared by the commands that compute a CDT (`mesh`, `cdt`): how to compute it and what to
// report. Parsed here once so both commands accept the same spellings.
#pragma once
#include <functional>
#include <string>

#include "args.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/snap.h"

namespace sweepcdt::cli {

struct RunOptions {
  Algorithm algorithm = mesh_defaults().algorithm;
  SteinerMode steiner = mesh_defaults().steiner;  // --steiner auto|none (`cdt` sets none)
  FacetMode facets = mesh_defaults().facets;      // --facets triangles|coplanar (3D)
  bool keep_steiner = false;  // --keep-steiner-points: skip deleting the Steiner points a CDT can do without
  double snap = 0;  // --snap TOL: snap surface coordinates first (sweepcdt/io/snap.h); 0 = exact input
  bool check = false;      // --check: validate the result again before writing it
  std::string stats_file;  // --stats FILE.json
  bool quiet = false;      // --quiet: errors only
  unsigned core_threads = 0;  // threads inside one computation (Options::threads): the cores a batch leaves per file
};

const char* to_string(SteinerMode mode);  // "auto", "none"
const char* to_string(FacetMode mode);    // "triangles", "coplanar"

// The core options of a run: what the user chose, plus where statistics and progress go.
Options core_options(const RunOptions& options, CdtStatistics* statistics, std::function<bool(const Progress&)> progress);

// --snap's bounds (io::kLargestSnap): it repairs rounding noise, not modelling error.
double parse_snap(const std::string& text);

// Consumes one of the shared options at the reader's position; false if it is none of them.
bool read_run_option(ArgReader& args, RunOptions& options);

// Consumes `--facets triangles|coplanar` (also `check`'s: the mode a mesh was made with).
bool read_facets_option(ArgReader& args, FacetMode& facets);

}  // namespace sweepcdt::cli
