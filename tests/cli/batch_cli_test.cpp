// `sweepcdt mesh INPUT... --out-dir DIR`: one output per input, the same bytes with any number of
// threads, a message per file, the worst exit code, and nothing for the files that fail.
#include "cli_run.h"

namespace sweepcdt::cli::testing {
namespace {

TEST(CliBatch, ThreadsGiveByteIdenticalFiles) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  std::string inputs;
  const char* names[] = {"off/icosahedron.off", "gltf/Box.gltf", "gltf/two_objects_inverse_materials.gltf", "glb/cubevc.glb",
                         "drc/cube_att.drc", "glb/moon.glb"};
  for (const char* name : names) inputs += " " + quoted(shared_data() / name);
  for (const char* format : {"vtu", "msh"}) {
    const CliRun one = run("mesh" + inputs + " --format " + format + " --out-dir " + quoted(dir.path() / "one") + " --threads 1", dir);
    ASSERT_EQ(one.exit_code, 0) << one.out;
    const CliRun three = run("mesh" + inputs + " --format " + format + " --out-dir " + quoted(dir.path() / "three") + " --threads 3", dir);
    ASSERT_EQ(three.exit_code, 0) << three.out;
    const auto files = files_in(dir.path() / "one");
    EXPECT_EQ(files.size(), std::size(names));
    EXPECT_EQ(files_in(dir.path() / "three"), files);
    for (const auto& f : files) EXPECT_EQ(bytes_of(dir.path() / "one" / f), bytes_of(dir.path() / "three" / f)) << f;
    for (const char* name : names) EXPECT_TRUE(three.says(std::string(name) + " -> ")) << three.out;  // a line per file
    fs::remove_all(dir.path() / "one");
    fs::remove_all(dir.path() / "three");
  }
}

TEST(CliBatch, FailuresLeaveNothingAndTheWorstCodeIsReturned) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto out = dir.path() / "out";
  const std::string good = quoted(shared_data() / "off/icosahedron.off");
  const std::string open = quoted(shared_data() / "bad/open_cube.off");
  const std::string no_cdt = quoted(write_schonhardt(dir));  // with --steiner none
  const CliRun r = run("mesh " + good + " " + open + " " + no_cdt + " --steiner none --out-dir " + quoted(out) + " --threads 2", dir);
  EXPECT_EQ(r.exit_code, 3) << "bad input (3) outranks no CDT (4)\n" << r.out;
  EXPECT_EQ(files_in(out), std::set<std::string>{"icosahedron.mesh"}) << r.out;
  EXPECT_TRUE(r.says("1 of 3 files converted")) << r.out;
  EXPECT_TRUE(r.says("open_cube.off: not a closed surface")) << r.out;
  EXPECT_TRUE(r.says("schonhardt.off: ")) << r.out;
  EXPECT_TRUE(r.says("witness vertices")) << r.out;

  const CliRun no_cdt_only = run("mesh " + good + " " + no_cdt + " --steiner none --out-dir " + quoted(dir.path() / "out2") + " --quiet", dir);
  EXPECT_EQ(no_cdt_only.exit_code, 4) << no_cdt_only.out;
  EXPECT_EQ(files_in(dir.path() / "out2"), std::set<std::string>{"icosahedron.mesh"});
  EXPECT_FALSE(no_cdt_only.says("icosahedron")) << "--quiet prints errors only\n" << no_cdt_only.out;
}

TEST(CliBatch, TetGenWritesThreeFilesPerInput) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const CliRun r = run("mesh " + quoted(shared_data() / "drc/cube_att.drc") + " " + quoted(shared_data() / "glb/cubevc.glb") +
                           " --format tetgen --out-dir " + quoted(dir.path() / "out"),
                       dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(files_in(dir.path() / "out"),
            (std::set<std::string>{"cube_att.node", "cube_att.ele", "cube_att.face", "cubevc.node", "cubevc.ele", "cubevc.face"}));
}

}  // namespace
}  // namespace sweepcdt::cli::testing
