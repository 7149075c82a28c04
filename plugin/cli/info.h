// `sweepcdt info INPUT [--json]`: what the importer sees in a surface file.
#pragma once
#include <iosfwd>
#include <string>

namespace sweepcdt::cli {

// Prints the report to `out` (errors that stop reading to `err`). Returns the process exit code:
// 0 for a valid closed surface, 3 for an unreadable or invalid one.
int run_info(const std::string& input, bool json, std::ostream& out, std::ostream& err);

}  // namespace sweepcdt::cli
