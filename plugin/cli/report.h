// What `mesh` and `cdt` print once a file is done, and how they write --stats: one wording for both.
#pragma once
#include <string>
#include <vector>

#include "file_result.h"
#include "progress.h"
#include "stats.h"

namespace sweepcdt::cli {

// Success: `done_line` and hints (unless quiet) and the warnings; failure: the message and (unless
// quiet) its details.
void report_file(Console& console, const std::string& done_line, const FileResult& r, bool quiet);

// --stats, when asked for: writes it, or reports why it could not; returns the run's exit code made
// worse by that failure.
int write_stats_if_asked(Console& console, const RunSummary& run, const std::vector<FileResult>& results);

}  // namespace sweepcdt::cli
