// `sweepcdt mesh` (and the bare `sweepcdt INPUT -o OUTPUT`): closed surfaces to volume meshes.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace sweepcdt::cli {

// `args` follow the word "mesh". Returns the exit code (the worst of all files).
int run_mesh(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace sweepcdt::cli
