// The CAD parts of tests/data/cad (FreeCAD exports: steiner_vs_tetgen_test.cpp says what they are)
// through the default command, as a FreeCAD user runs it, and `sweepcdt check` on every result: the
// default meshes them all, and each mesh is exactly the CDT of its part. And parts of 3D prints as
// OpenSCAD exports them (tests/data/scad/README.md), surfaces like scans' (tests/data/scan), and
// surfaces decimated by MeshLab (tests/data/decimated), and parts placed at an angle (tests/data/tilted).
#include <algorithm>
#include <cstdlib>

#include "cli_run.h"

namespace sweepcdt::cli::testing {
namespace {

// `sweepcdt SURFACE -o OUTPUT` with the default options, then `sweepcdt check` of the result (when
// there is one).
struct Meshed {
  CliRun mesh, check;
};
Meshed mesh_and_check(const fs::path& surface, const fs::path& output, const TempDir& dir) {
  Meshed m{run(quoted(surface) + " -o " + quoted(output), dir), {-1, ""}};
  if (m.mesh.exit_code == 0) m.check = run("check " + quoted(surface) + " " + quoted(output), dir);
  return m;
}

// The surfaces in tests/data/FOLDER (STL, OBJ, PLY), sorted.
std::vector<fs::path> surfaces_in(const std::string& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(SWEEPCDT_TEST_DATA) / folder))
    if (const auto ext = entry.path().extension(); ext == ".stl" || ext == ".obj" || ext == ".ply") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(CliCad, DefaultCommandMeshesCadPartsAndCheckVerifiesThem) {
  const std::vector<fs::path> files = surfaces_in("cad");
  ASSERT_GE(files.size(), 20u) << "tests/data/cad";
  TempDir dir;
  int meshed = 0;
  for (const fs::path& file : files) {
    const Meshed m = mesh_and_check(file, dir.path() / (file.stem().string() + file.extension().string().substr(1) + ".mesh"), dir);
    ASSERT_EQ(m.mesh.exit_code, 0) << file << "\n" << m.mesh.out;
    EXPECT_EQ(m.check.exit_code, 0) << file << "\n" << m.check.out;
    EXPECT_TRUE(m.check.says("coplanar facets, tiling them;")) << m.check.out;
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
    const fs::path stl = dir.path() / (std::string(part) + ".stl");
    const std::string exported = "openscad -o " + quoted(stl) + " " + quoted(folder / (std::string(part) + ".scad")) + " > /dev/null 2>&1";
    ASSERT_EQ(std::system(exported.c_str()), 0) << exported;
    const Meshed m = mesh_and_check(stl, dir.path() / (std::string(part) + ".mesh"), dir);
    ASSERT_EQ(m.mesh.exit_code, 0) << part << "\n" << m.mesh.out;
    EXPECT_FALSE(m.mesh.says(" 0 Steiner points")) << part << ": no Steiner point needed, nothing exercised\n" << m.mesh.out;
    EXPECT_EQ(m.check.exit_code, 0) << part << "\n" << m.check.out;
  }
}

// Surfaces as scanners and voxel tools make them (tests/data/scan/make_scan_surfaces.py: marching
// tetrahedra of metaballs and of a gyroid lattice, full of slivers; a bumpy organic shell), made
// here, as float STL and as 6-decimal OBJ: every one meshes by default, and `check` verifies it.
TEST(CliCad, ScanLikeSurfacesMeshByDefaultAndCheckVerifiesThem) {
  TempDir dir;
  const std::string make = "python3 " + quoted(fs::path(SWEEPCDT_TEST_DATA) / "scan" / "make_scan_surfaces.py") + " " + quoted(dir.path()) +
                           " --grid 16 --level 4";
  ASSERT_EQ(std::system(make.c_str()), 0) << make;
  int with_points = 0;
  for (const char* name : {"blobs_16.stl", "blobs_16.obj", "gyroid_16.stl", "shell_4.obj"}) {
    const Meshed m = mesh_and_check(dir.path() / name, dir.path() / (std::string(name) + ".mesh"), dir);
    ASSERT_EQ(m.mesh.exit_code, 0) << name << "\n" << m.mesh.out;
    with_points += !m.mesh.says(" 0 Steiner points");
    EXPECT_EQ(m.check.exit_code, 0) << name << "\n" << m.check.out;
  }
  EXPECT_GE(with_points, 3) << "the slivers need Steiner points: nothing exercised";
}

// Surfaces as MeshLab users simplify them (tests/data/decimated: quadric edge collapse of CAD parts,
// faces flat only up to rounding): every one meshes by default, and `check` verifies it.
TEST(CliCad, DecimatedSurfacesMeshByDefaultAndCheckVerifiesThem) {
  const std::vector<fs::path> files = surfaces_in("decimated");
  ASSERT_EQ(files.size(), 6u) << "tests/data/decimated";
  TempDir dir;
  int with_points = 0;
  for (const fs::path& file : files) {
    const Meshed m = mesh_and_check(file, dir.path() / (file.stem().string() + ".mesh"), dir);
    ASSERT_EQ(m.mesh.exit_code, 0) << file << "\n" << m.mesh.out;
    with_points += !m.mesh.says(" 0 Steiner points");
    EXPECT_EQ(m.check.exit_code, 0) << file << "\n" << m.check.out;
  }
  EXPECT_GE(with_points, 5) << "the thin triangles need Steiner points: nothing exercised";
}

// Parts placed at an angle (tests/data/tilted: thin walls and a drilled board, turned and written
// in floats): no face is exactly flat, so the fans of long thin triangles on them need Steiner
// points — 134290 added on the board, 18291 kept. Every one meshes by default, and `check` verifies it.
TEST(CliCad, PartsPlacedAtAnAngleMeshByDefaultAndCheckVerifiesThem) {
  const std::vector<fs::path> files = surfaces_in("tilted");
  ASSERT_EQ(files.size(), 4u) << "tests/data/tilted";
  TempDir dir;
  for (const fs::path& file : files) {
    const Meshed m = mesh_and_check(file, dir.path() / (file.stem().string() + ".mesh"), dir);
    ASSERT_EQ(m.mesh.exit_code, 0) << file << "\n" << m.mesh.out;
    EXPECT_FALSE(m.mesh.says(" 0 Steiner points")) << file << ": the tilt bends every face, and its fans need points\n" << m.mesh.out;
    EXPECT_EQ(m.check.exit_code, 0) << file << "\n" << m.check.out;
  }
}

}  // namespace
}  // namespace sweepcdt::cli::testing
