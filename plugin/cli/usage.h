// Help texts: `sweepcdt --help`, `sweepcdt help [COMMAND]`, `sweepcdt COMMAND --help`, and the short
// usage printed (on stderr) after a usage error.
#pragma once
#include <string>

namespace sweepcdt::cli {

std::string general_help();
std::string general_usage();
std::string mesh_help();
std::string mesh_usage();
std::string check_help();
std::string check_usage();
std::string cdt_help();
std::string cdt_usage();
std::string info_help();
std::string info_usage();
std::string exit_codes_text();

}  // namespace sweepcdt::cli
