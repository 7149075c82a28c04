// The CAD parts of tests/data/cad (FreeCAD exports: steiner_vs_tetgen_test.cpp says what they are)
// through the default command, as a FreeCAD user runs it, and `sweepcdt check` on every result: the
// default meshes them all, and each mesh is exactly the CDT of its part. And parts of 3D prints as
// OpenSCAD exports them (tests/data/scad/README.md).
#include <algorithm>
#include <cstdlib>

#include "cli_run.h"

namespace sweepcdt::cli::testing {
namespace {

TEST(CliCad, DefaultCommandMeshesCadPartsAndCheckVerifiesThem) {
  const fs::path folder = fs::path(SWEEPCDT_TEST_DATA) / "cad";
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder))
    if (const auto ext = entry.path().extension(); ext == ".stl" || ext == ".obj" || ext == ".ply") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 20u) << folder;
  TempDir dir;
  int meshed = 0;
  for (const fs::path& file : files) {
    const fs::path output = dir.path() / (file.stem().string() + file.extension().string().substr(1) + ".mesh");
    const CliRun r = run(quoted(file) + " -o " + quoted(output), dir);
    ASSERT_EQ(r.exit_code, 0) << file << "\n" << r.out;
    const CliRun ok = run("check " + quoted(file) + " " + quoted(output), dir);
    EXPECT_EQ(ok.exit_code, 0) << file << "\n" << ok.out;
    EXPECT_TRUE(ok.says("coplanar facets, tiling them;")) << ok.out;
    ++meshed;
  }
  EXPECT_EQ(meshed, static_cast<int>(files.size()));
}

// OpenSCAD's ASCII STL (double coordinates, faces flat only up to 6 significant digits, CSG's thin
// triangles) through the default command, exported here as a user exports it: every part meshes,
// with Steiner points, and `check` verifies each result. OpenSCAD is installed by scripts/setup.sh.
TEST(CliCad, OpenScadExportsMeshByDefaultAndCheckVerifiesThem) {
  ASSERT_EQ(std::system("command -v openscad > /dev/null"), 0) << "openscad not found: run scripts/setup.sh";
  const fs::path folder = fs::path(SWEEPCDT_TEST_DATA) / "scad";
  TempDir dir;
  for (const char* part : {"l_bracket", "spur_gear", "knurled_knob", "twisted_vase"}) {
    const fs::path stl = dir.path() / (std::string(part) + ".stl"), output = dir.path() / (std::string(part) + ".mesh");
    const std::string exported = "openscad -o " + quoted(stl) + " " + quoted(folder / (std::string(part) + ".scad")) + " > /dev/null 2>&1";
    ASSERT_EQ(std::system(exported.c_str()), 0) << exported;
    const CliRun r = run(quoted(stl) + " -o " + quoted(output), dir);
    ASSERT_EQ(r.exit_code, 0) << part << "\n" << r.out;
    EXPECT_FALSE(r.says(" 0 Steiner points")) << part << ": no Steiner point needed, nothing exercised\n" << r.out;
    const CliRun ok = run("check " + quoted(stl) + " " + quoted(output), dir);
    EXPECT_EQ(ok.exit_code, 0) << part << "\n" << ok.out;
  }
}

}  // namespace
}  // namespace sweepcdt::cli::testing
