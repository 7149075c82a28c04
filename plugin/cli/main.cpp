// sweepcdt — the command-line front end. main() only parses arguments and dispatches; the work is in
// the library (sweepcdt::io, sweepcdt::core) and in one file per subcommand.
#include <iostream>
#include <string>
#include <vector>

#include "info.h"

namespace {

constexpr const char* kUsage =
    "usage: sweepcdt info INPUT [--json]\n"
    "  info    what the importer sees in a surface file (OFF, STL, OBJ, PLY, glTF/GLB, Draco):\n"
    "          counts, welding, closed, manifold, orientation, shells and nesting, self-intersections\n"
    "exit codes: 0 valid closed surface, 2 usage error, 3 unreadable or invalid input\n";

int usage(const std::string& problem) {
  if (!problem.empty()) std::cerr << "sweepcdt: " << problem << "\n";
  std::cerr << kUsage;
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return usage("no command given");
  if (args[0] == "-h" || args[0] == "--help") {
    std::cout << kUsage;
    return 0;
  }
  if (args[0] != "info") return usage("unknown command '" + args[0] + "'");
  std::string input;
  bool json = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--json") json = true;
    else if (args[i].size() > 1 && args[i][0] == '-') return usage("unknown option '" + args[i] + "'");
    else if (input.empty()) input = args[i];
    else return usage("more than one INPUT");
  }
  if (input.empty()) return usage("info needs an INPUT file");
  return sweepcdt::cli::run_info(input, json, std::cout, std::cerr);
}
