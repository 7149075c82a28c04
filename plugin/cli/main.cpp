// sweepcdt — the command-line front end. main() only dispatches to one file per subcommand; the work
// is in the library (sweepcdt::io, sweepcdt::core).
//
//   sweepcdt INPUT -o OUTPUT          = sweepcdt mesh INPUT -o OUTPUT
//   sweepcdt mesh | check | cdt | info | help ...
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cdt_command.h"
#include "check_command.h"
#include "exit_codes.h"
#include "info.h"
#include "mesh_command.h"
#include "usage.h"

namespace {

using namespace sweepcdt::cli;

int usage_error(const std::string& problem, const std::string& usage) {
  std::cerr << "sweepcdt: " << problem << "\n" << usage;
  return kUsage;
}

int run_info_command(const std::vector<std::string>& args) {
  std::string input;
  bool json = false;
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::cout << info_help();
      return kOk;
    }
    if (a == "--json") json = true;
    else if (a.size() > 1 && a[0] == '-') return usage_error("unknown option '" + a + "'", info_usage());
    else if (input.empty()) input = a;
    else return usage_error("more than one INPUT", info_usage());
  }
  if (input.empty()) return usage_error("info needs an INPUT file", info_usage());
  return run_info(input, json, std::cout, std::cerr);
}

int help(const std::vector<std::string>& args) {
  if (args.empty()) return std::cout << general_help(), kOk;
  if (args.size() > 1) return usage_error("help takes at most one COMMAND", general_usage());
  const std::string& c = args[0];
  if (c == "mesh") std::cout << mesh_help();
  else if (c == "check") std::cout << check_help();
  else if (c == "cdt") std::cout << cdt_help();
  else if (c == "info") std::cout << info_help();
  else if (c == "help") std::cout << general_help();
  else return usage_error("no command '" + c + "'", general_usage());
  return kOk;
}

// A first word that is no command is the INPUT of an implicit `mesh` — if it can be a file name.
// A bare word that names no file ("chek") is a mistyped command, not a missing input.
bool looks_like_input(const std::string& word) {
  return word[0] == '-' || word.find('.') != std::string::npos || word.find('/') != std::string::npos ||
         std::filesystem::exists(word);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return usage_error("no command or INPUT given", general_usage());
  const std::string& first = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (first == "-h" || first == "--help") return help({});
  if (first == "--version" || first == "-V") {
    std::cout << "sweepcdt " SWEEPCDT_VERSION "\n";
    return kOk;
  }
  if (first == "help") return help(rest);
  if (first == "info") return run_info_command(rest);
  if (first == "mesh") return run_mesh(rest, std::cout, std::cerr);
  if (first == "check") return run_check(rest, std::cout, std::cerr);
  if (first == "cdt") return run_cdt(rest, std::cout, std::cerr);
  if (!first.empty() && looks_like_input(first)) return run_mesh(args, std::cout, std::cerr);
  return usage_error("unknown command '" + first + "'", general_usage());
}
