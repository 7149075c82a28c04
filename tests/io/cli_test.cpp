// The sweepcdt executable's `info` subcommand: exit codes (0 valid, 3 invalid or unreadable,
// 2 usage) and what it prints.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "surface_builders.h"
#include "sweepcdt/io/write_surface.h"

namespace sweepcdt::io {
namespace {

struct CliRun {
  int exit_code;
  std::string out;  // stdout and stderr
};

CliRun run(const std::string& args, const testing::TempDir& dir) {
  const auto log = dir.path() / "log.txt";
  const std::string cmd = std::string(SWEEPCDT_CLI) + " " + args + " > " + log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

TEST(CliInfo, ValidSurfaceExitsZeroAndSaysWhatItSees) {
  testing::TempDir dir;
  Soup soup = testing::cube_soup(0, 4);
  testing::add_cube(soup, 1, 2);  // a cavity, given outward: the repair reverses it
  write_surface(dir.path() / "cube.stl", soup, Format::StlBinary);
  const CliRun r = run("info " + (dir.path() / "cube.stl").string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  for (const char* expected : {"STL binary", "triangles:       24", "vertices:        16 after welding (72 in the file)", "closed:          yes",
                               "shells:          2 (2 closed, 1 nested)", "cavity, depth 1, inside shell 0, reversed", "repaired: 12 triangles reversed",
                               "self-intersecting pairs: 0", "[0, 0, 0] - [4, 4, 4]"})
    EXPECT_NE(r.out.find(expected), std::string::npos) << "missing '" << expected << "' in\n" << r.out;
  const CliRun json = run("info --json " + (dir.path() / "cube.stl").string(), dir);
  EXPECT_EQ(json.exit_code, 0);
  EXPECT_NE(json.out.find("\"valid\": true"), std::string::npos) << json.out;
}

TEST(CliInfo, InvalidSurfaceExitsThreeAndListsProblems) {
  testing::TempDir dir;
  Soup soup = testing::cube_soup();
  soup.triangles.resize(soup.triangles.size() - 3);
  write_surface(dir.path() / "open.off", soup, Format::Off);
  const CliRun r = run("info " + (dir.path() / "open.off").string(), dir);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.out.find("3 boundary-edge"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the surface is open"), std::string::npos) << r.out;
}

TEST(CliInfo, MalformedFileExitsThreeWithFileAndLine) {
  testing::TempDir dir;
  const auto file = dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n");
  const CliRun r = run("info " + file.string(), dir);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.out.find(file.string() + ":4:"), std::string::npos) << r.out;
  EXPECT_EQ(run("info " + (dir.path() / "missing.stl").string(), dir).exit_code, 3);
}

TEST(CliInfo, UsageErrorsExitTwo) {
  testing::TempDir dir;
  EXPECT_EQ(run("", dir).exit_code, 2);
  EXPECT_EQ(run("info", dir).exit_code, 2);
  EXPECT_EQ(run("frobnicate x.off", dir).exit_code, 2);
  const CliRun r = run("info x.off --verbose", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown option '--verbose'"), std::string::npos);
  EXPECT_NE(r.out.find("usage: sweepcdt info INPUT [--json]"), std::string::npos);
}

}  // namespace
}  // namespace sweepcdt::io
