#include "report.h"

#include "errors.h"
#include "exit_codes.h"

namespace sweepcdt::cli {

void report_file(Console& console, const std::string& done_line, const FileResult& r, bool quiet) {
  if (r.code == kOk) {
    if (!quiet) console.line(done_line);
    for (const auto& w : r.warnings) console.line("sweepcdt: warning: " + w);
    if (!quiet)
      for (const auto& d : r.details) console.line("  " + d);  // hints
    return;
  }
  console.line("sweepcdt: " + r.message);
  if (!quiet)
    for (const auto& d : r.details) console.line("  " + d);
}

int write_stats_if_asked(Console& console, const RunSummary& run, const std::vector<FileResult>& results) {
  if (run.options.stats_file.empty()) return run.exit_code;
  try {
    write_stats(run.options.stats_file, run, results);
    return run.exit_code;
  } catch (...) {
    const Failure f = describe_current_exception(run.options.stats_file, true);
    console.line("sweepcdt: " + f.message);
    return worst(run.exit_code, f.code);
  }
}

}  // namespace sweepcdt::cli
