// Running the built sweepcdt binary from tests: exit code and everything it printed, files in a
// folder, and the shared meshes' paths.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "io_test_util.h"
#include "sweepcdt/io/write_surface.h"
#include "test_shapes.h"

namespace sweepcdt::cli::testing {

namespace fs = std::filesystem;
using io::testing::TempDir;

struct CliRun {
  int exit_code;
  std::string out;  // stdout and stderr
  bool says(const std::string& text) const { return out.find(text) != std::string::npos; }
};

inline std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// Runs `sweepcdt ARGS` (ARGS as shell words), output captured to a log in `dir` (not listed by files_in).
// `hang_guard`: if above 0, the run is killed after that many seconds (exit 124): a guard against a
// hang only, far above any run's time.
inline CliRun run(const std::string& args, const TempDir& dir, int hang_guard = 0) {
  const auto log = dir.path() / ".log";
  const std::string guard = hang_guard > 0 ? "timeout " + std::to_string(hang_guard) + " " : "";
  const std::string cmd = guard + std::string(SWEEPCDT_CLI) + " " + args + " > " + quoted(log) + " 2>&1 < /dev/null";
  const int status = std::system(cmd.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

// Names of the files in `folder` (not recursive), without the run log.
inline std::set<std::string> files_in(const fs::path& folder) {
  std::set<std::string> names;
  if (!fs::exists(folder)) return names;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.path().filename() != ".log") names.insert(e.path().filename().string());
  return names;
}

inline std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline fs::path shared_data() { return fs::path(SWEEPCDT_SHARED_DATA); }

// The valid closed shared meshes, which all get a CDT with Steiner points, but gearwheel: it takes
// 20 s and 49k Steiner points (its faces are flat only to within rounding), so it has tests of its
// own (snap_cli_test.cpp).
inline const char* const kMeshesWithCdt[] = {"off/icosahedron.off", "off/femur.off", "stl_ascii/t13_data_ascii.stl",
                                             "stl_binary/spot.stl", "stl_binary/torus.stl", "gltf/Box.gltf",
                                             "gltf/two_objects_inverse_materials.gltf", "glb/moon.glb", "glb/cubevc.glb",
                                             "drc/cube_att.drc", "drc/knot1.drc", "stl_binary/thingi_1706459.stl"};

// Schönhardt's twisted prism (no tetrahedralization without Steiner points) as an OFF file in dir.
inline fs::path write_schonhardt(const TempDir& dir, const std::string& name = "schonhardt.off") {
  const fs::path file = dir.path() / name;
  io::write_surface(file, fixtures::twisted_prism(0.5), io::Format::Off);
  return file;
}

// Skips, saying why, when the shared data is not there (DESIGN.md: CI has shared/ beside the checkout).
#define SWEEPCDT_REQUIRE_SHARED_DATA()                                                          \
  do {                                                                                          \
    if (!std::filesystem::exists(::sweepcdt::cli::testing::shared_data() / "MANIFEST.md"))     \
      GTEST_SKIP() << "shared data not found at " << ::sweepcdt::cli::testing::shared_data();  \
  } while (0)

}  // namespace sweepcdt::cli::testing
