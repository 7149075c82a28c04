// `sweepcdt cdt FILE -o OUT`: the CDT of a PLC file in any dimension (2..5).
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace sweepcdt::cli {

// `args` follow the word "cdt". Returns the exit code.
int run_cdt(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace sweepcdt::cli
