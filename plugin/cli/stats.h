// --stats FILE.json: counts, times and memory of a run, for scripts and benchmarks.
#pragma once
#include <string>
#include <vector>

#include "file_result.h"
#include "run_options.h"

namespace sweepcdt::cli {

struct RunSummary {
  std::string command;  // "mesh" or "cdt"
  RunOptions options;
  unsigned threads = 1;
  double seconds = 0;   // wall time of the whole run
  int exit_code = 0;
};

// Peak resident memory of the process so far (getrusage), in bytes.
uint64_t peak_memory_bytes();

// Writes the JSON atomically (temporary file in the same folder, then rename): a reader never sees
// half a file. Throws io::InputError (Unreadable) naming `file` when it cannot be written.
void write_stats(const std::string& file, const RunSummary& run, const std::vector<FileResult>& results);

}  // namespace sweepcdt::cli
