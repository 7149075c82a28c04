// `--snap TOL` (sweepcdt/io/snap.h), as a user meets it: the hint that suggests it when a CAD mesh
// needs many Steiner points or has no CDT, the mesh it then gives, what the summary and --stats say, `check --snap`, and the
// tolerances it refuses.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

#include "cad_noise.h"
#include "cli_run.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/io/volume_mesh.h"
#include "test_shapes.h"

namespace sweepcdt::cli::testing {
namespace {

const char kGearwheel[] = "stl_ascii/gearwheel_ascii.stl";

// gearwheel's bottom face is z = 0 at most vertices and z = ±5e-17 at 241 others (CAD noise); one
// more vertex has y = 7.348e-16 beside y = 7.347881e-16. 242 points, one coordinate each: counted
// from the STL text by a separate script (distinct vertices; the same greedy clusters), not taken
// from sweepcdt's output. The exact path meshes it as given, with many Steiner points (each noisy
// triangle is a facet of its own), and the summary says what --snap would do.
TEST(CliSnap, GearwheelMeshesAsGivenAndTheSummarySaysWhatToTry) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto out = dir.path() / "g.mesh";
  const CliRun r = run(quoted(shared_data() / kGearwheel) + " -o " + quoted(out), dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(r.says("hint: moving 242 vertices by up to 5.4e-17")) << r.out;
  EXPECT_TRUE(r.says("`--snap 1e-12` makes faces that are flat by design exactly flat, each one facet (and needs fewer Steiner points)")) << r.out;
  const CliRun check = run("check " + quoted(shared_data() / kGearwheel) + " " + quoted(out), dir);
  EXPECT_EQ(check.exit_code, 0) << check.out;
  // With --facets triangles, the hint names coplanar facets too (on a smaller part with noise: the
  // gearwheel takes 96 s that way).
  const auto noisy = dir.path() / "two_bodies_noisy.off";
  io::write_surface(noisy, sweepcdt::testing::with_cad_noise(io::import_plc(fs::path(SWEEPCDT_TEST_DATA) / "cad/two_bodies_fine.stl"), 0.5, 1),
                    io::Format::Off);
  const CliRun triangles = run(quoted(noisy) + " --facets triangles -o " + quoted(dir.path() / "t.mesh"), dir);
  EXPECT_EQ(triangles.exit_code, 0) << triangles.out;
  EXPECT_TRUE(triangles.says("`--snap 1e-12 --facets coplanar` makes faces")) << triangles.out;
  // Few Steiner points (the Schönhardt prism's handful), or --quiet: no hint.
  const CliRun prism = run(quoted(write_schonhardt(dir)) + " -o " + quoted(dir.path() / "p.mesh"), dir);
  EXPECT_EQ(prism.exit_code, 0) << prism.out;
  EXPECT_FALSE(prism.says("hint:")) << prism.out;
  const CliRun quiet = run(quoted(noisy) + " -q -o " + quoted(dir.path() / "q.mesh"), dir);
  EXPECT_EQ(quiet.exit_code, 0) << quiet.out;
  EXPECT_FALSE(quiet.says("hint:")) << quiet.out;
}

// Without a CDT as given (--steiner none) the error says what to try.
// The hint's count is checked against the noise itself: snapping moves only points the noise moved.
TEST(CliSnap, NoCdtMessageSaysWhatToTry) {
  TempDir dir;
  const auto noisy = dir.path() / "two_bodies_noisy.off";
  const Plc<3> clean = io::import_plc(fs::path(SWEEPCDT_TEST_DATA) / "cad/two_bodies_fine.stl");
  const Plc<3> moved = sweepcdt::testing::with_cad_noise(clean, 0.5, 1);
  std::size_t noised = 0;
  for (uint32_t v = 0; v < clean.num_points(); ++v)
    noised += !std::equal(clean.point(v), clean.point(v) + 3, moved.point(v));
  io::write_surface(noisy, moved, io::Format::Off);
  const CliRun r = run("--steiner none " + quoted(noisy) + " -o " + quoted(dir.path() / "n.mesh"), dir);
  EXPECT_EQ(r.exit_code, 4) << r.out;
  const auto at = r.out.find("hint: moving ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::size_t hinted = std::stoul(r.out.substr(at + 13));
  EXPECT_GT(hinted, noised / 2) << r.out;
  EXPECT_LE(hinted, noised) << r.out;
  // Schönhardt's prism has rounding noise too (6.7e-16 for 0), but snapping it flattens nothing: no hint.
  const CliRun prism = run("--steiner none " + quoted(write_schonhardt(dir)) + " -o " + quoted(dir.path() / "p.mesh"), dir);
  EXPECT_EQ(prism.exit_code, 4) << prism.out;
  EXPECT_FALSE(prism.says("hint:")) << prism.out;
}

TEST(CliSnap, GearwheelSnappedWithCoplanarFacetsMeshesAndValidates) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto out = dir.path() / "g.vtu";
  const auto stats = dir.path() / "g.json";
  const CliRun r = run(quoted(shared_data() / kGearwheel) + " -o " + quoted(out) + " --snap 1e-12 --facets coplanar --check --stats " +
                           quoted(stats),
                       dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(r.says("242 points snapped (by up to 5.41e-17)")) << r.out;
  EXPECT_TRUE(r.says("checked")) << r.out;
  const auto json = nlohmann::json::parse(bytes_of(stats));
  EXPECT_EQ(json["snap"], 1e-12);
  const auto& snap = json["files"][0]["snap"];
  EXPECT_EQ(snap["points_moved"], 242);
  EXPECT_EQ(snap["coordinates_moved"], 242);  // 241 z, 1 y
  EXPECT_EQ(snap["points_merged"], 0);
  EXPECT_GT(snap["edges_flattened"].get<int>(), 100);
  EXPECT_EQ(snap["largest_move"], 5.405771e-17);
  // The mesh's points are the snapped input's: no z between -1e-16 and 1e-16 other than 0.
  const io::VolumeMesh mesh = io::read_volume_mesh(out);
  EXPECT_GT(mesh.num_tetrahedra(), 1000u);
  std::size_t on_bottom = 0;
  for (std::size_t i = 2; i < mesh.points.size(); i += 3)
    if (std::abs(mesh.points[i]) < 1e-16) {
      EXPECT_EQ(mesh.points[i], 0.0) << i / 3;
      ++on_bottom;
    }
  EXPECT_GT(on_bottom, 241u);  // the snapped points and those at 0 before
  // `check` verifies it from the file, given the same --snap and --facets; not without the snap.
  const CliRun checked = run("check " + quoted(shared_data() / kGearwheel) + " " + quoted(out) + " --facets coplanar --snap 1e-12", dir);
  EXPECT_EQ(checked.exit_code, 0) << checked.out;
  const CliRun unsnapped = run("check " + quoted(shared_data() / kGearwheel) + " " + quoted(out) + " --facets coplanar", dir);
  EXPECT_EQ(unsnapped.exit_code, 6) << unsnapped.out;
}

// A cube whose bottom face has one noisy vertex, meshed with --snap: `check` must be told the same
// tolerance, since the mesh's points are the snapped ones.
TEST(CliSnap, CheckReadsTheInputSnappedLikeMesh) {
  TempDir dir;
  Plc<3> cube = fixtures::unit_cube_surface();
  cube.points[3 * 3 + 2] = -4e-17;  // point 3 = (1, 1, 0)
  const auto input = dir.path() / "noisy_cube.off";
  io::write_surface(input, cube, io::Format::Off);
  const auto out = dir.path() / "cube.mesh";
  const CliRun meshed = run(quoted(input) + " -o " + quoted(out) + " --snap 1e-12", dir);
  ASSERT_EQ(meshed.exit_code, 0) << meshed.out;
  EXPECT_TRUE(meshed.says("1 points snapped (by up to 4e-17)")) << meshed.out;
  const CliRun exact = run("check " + quoted(input) + " " + quoted(out), dir);
  EXPECT_EQ(exact.exit_code, 6) << exact.out;
  const CliRun snapped = run("check " + quoted(input) + " " + quoted(out) + " --snap 1e-12", dir);
  EXPECT_EQ(snapped.exit_code, 0) << snapped.out;
}

TEST(CliSnap, ToleranceMustBeAboveZeroAndAtMostOneThousandth) {
  TempDir dir;
  const auto input = write_schonhardt(dir);
  for (const char* bad : {"0", "-1e-12", "abc", "1e-2", "nan", "inf", "1e-12x", ""}) {
    const CliRun r = run(quoted(input) + " -o " + quoted(dir.path() / "p.mesh") + " --snap '" + bad + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.out;
    EXPECT_TRUE(r.says("--snap needs a")) << bad << "\n" << r.out;  // "a value" when it looks like an option
  }
  const CliRun check = run("check " + quoted(input) + " " + quoted(input) + " --snap 1", dir);
  EXPECT_EQ(check.exit_code, 2) << check.out;
  // `cdt` reads PLC files as given: --snap there is refused, not ignored.
  const auto plc = dir.write("square.poly", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n0 0\n0\n");
  const CliRun cdt = run("cdt " + quoted(plc) + " -o " + quoted(dir.path() / "square.node") + " --snap 1e-12", dir);
  EXPECT_EQ(cdt.exit_code, 2) << cdt.out;
  EXPECT_TRUE(cdt.says("`cdt` takes a PLC file exactly as given")) << cdt.out;
  EXPECT_TRUE(files_in(dir.path()) == (std::set<std::string>{"schonhardt.off", "square.poly"}));
}

}  // namespace
}  // namespace sweepcdt::cli::testing
