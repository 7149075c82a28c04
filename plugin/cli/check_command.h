// `sweepcdt check INPUT OUTPUT`: is the volume mesh OUTPUT the CDT of the surface INPUT?
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace sweepcdt::cli {

// `args` follow the word "check". Exit 0 valid, 6 not valid, 3 unreadable, 2 usage.
int run_check(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace sweepcdt::cli
