// The CAD parts of tests/data/cad (FreeCAD exports: steiner_vs_tetgen_test.cpp says what they are)
// through the default command, as a FreeCAD user runs it, and `sweepcdt check` on every result: the
// default meshes them all, and each mesh is exactly the CDT of its part.
#include <algorithm>

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

}  // namespace
}  // namespace sweepcdt::cli::testing
