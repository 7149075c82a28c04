// Running the independent checkers (meshio, gmsh, ccx, tetgen) as subprocesses. A missing tool is a
// test FAILURE naming the Debian package (scripts/setup.sh installs them), never a silent skip.
#pragma once
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>

namespace sweepcdt::io::testing {

struct ToolRun {
  int status = -1;  // exit status
  std::string output;  // stdout and stderr
};

inline ToolRun run_tool(const std::string& command) {
  ToolRun r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// True if `program` can be run; otherwise records a failure naming the package that provides it.
inline bool require_tool(const std::string& program, const std::string& package) {
  if (run_tool("command -v " + program).status == 0) return true;
  ADD_FAILURE() << program << " is not installed: install the Debian package " << package << " (scripts/setup.sh does)";
  return false;
}

inline bool require_meshio() {
  if (!std::filesystem::exists("/usr/bin/python3")) {
    ADD_FAILURE() << "/usr/bin/python3 is missing: install python3-meshio (scripts/setup.sh does)";
    return false;
  }
  if (run_tool("/usr/bin/python3 -c 'import meshio, numpy'").status == 0) return true;
  ADD_FAILURE() << "python module meshio is missing: install the Debian package python3-meshio (scripts/setup.sh does)";
  return false;
}

inline std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

}  // namespace sweepcdt::io::testing
