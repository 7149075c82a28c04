// `sweepcdt INPUT -o OUTPUT`: the shared meshes in every output format (each output verified with
// `sweepcdt check`, which reads it back), the documented failures (exit 3 bad input, 4 no CDT,
// 5 unwritable output) leaving no file behind, --stats.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>


#include "cli_run.h"
#include "sweepcdt/io/volume_mesh.h"
#include "test_shapes.h"

namespace sweepcdt::cli::testing {
namespace {

const char* const kFormats[] = {"mesh", "vtu", "msh", "msh22", "tetgen", "inp"};

std::string extension(const std::string& format) {
  if (format == "msh22") return ".msh";
  if (format == "tetgen") return ".node";
  return "." + format;
}

// Every shared mesh that has a CDT, in every format: two batch runs (two threads; msh and msh22 both
// write .msh, so they cannot share a folder), then `check` on every output, which reads it back with
// io::read_volume_mesh and verifies it exactly.
TEST(CliMesh, SharedMeshesInEveryFormatPassCheck) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  std::string inputs;
  for (const char* name : kMeshesWithCdt) inputs += " " + quoted(shared_data() / name);
  const std::string n = std::to_string(std::size(kMeshesWithCdt));
  std::string log;
  for (const std::string formats : {"mesh,vtu,msh,tetgen,inp", "msh22"}) {
    const auto out = dir.path() / formats;
    const CliRun r = run("mesh" + inputs + " --out-dir " + quoted(out) + " --format " + formats + " --threads 2", dir);
    ASSERT_EQ(r.exit_code, 0) << formats << "\n" << r.out;
    EXPECT_TRUE(r.says(n + " of " + n + " files converted")) << r.out;
    log += r.out;
  }
  std::size_t rounded_files = 0;
  for (const char* name : kMeshesWithCdt) {
    const std::string stem = fs::path(name).stem().string();
    const auto exact = io::read_volume_mesh(dir.path() / "mesh,vtu,msh,tetgen,inp" / (stem + ".mesh")).points;
    for (const std::string format : kFormats) {
      const auto output = dir.path() / (format == "msh22" ? "msh22" : "mesh,vtu,msh,tetgen,inp") / (stem + extension(format));
      ASSERT_TRUE(fs::exists(output)) << output;
      if (format == "tetgen")
        for (const char* part : {".ele", ".face"}) EXPECT_TRUE(fs::exists(fs::path(output).replace_extension(part))) << output;
      const CliRun check = run("check " + quoted(shared_data() / name) + " " + quoted(output), dir);
      // Abaqus .inp rounds coordinates that do not fit CalculiX's 20-character fields (io's
      // write_abaqus.cpp): such a file is not exactly the CDT; mesh warns and check says so.
      const bool rounded = io::read_volume_mesh(output).points != exact;
      const bool warned = log.find("warning: " + output.string() + ": ") != std::string::npos;
      EXPECT_EQ(warned, rounded) << output << "\n" << log;
      if (rounded) {
        ++rounded_files;
        EXPECT_EQ(format, "inp") << name;
        EXPECT_EQ(check.exit_code, 6) << name << " as " << format << "\n" << check.out;
        EXPECT_TRUE(check.says("rounds coordinates")) << check.out;
        continue;
      }
      EXPECT_EQ(check.exit_code, 0) << name << " as " << format << "\n" << check.out;
      EXPECT_TRUE(check.says("valid: input vertices identical")) << check.out;
    }
  }
  std::printf("  %zu .inp files with rounded coordinates (warned, and rejected by check)\n", rounded_files);
}

// Several outputs of one input: one computation; if one cannot be written, none is left.
TEST(CliMesh, SeveralOutputsAllOrNone) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto input = quoted(shared_data() / "drc/cube_att.drc");
  const CliRun r = run(input + " -o " + quoted(dir.path() / "a.mesh") + " -o " + quoted(dir.path() / "a.node") + " -o " +
                           quoted(dir.path() / "a.msh"),
                       dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"a.mesh", "a.node", "a.ele", "a.face", "a.msh"}));
  const auto blocker = dir.write("blocker", "x");
  const CliRun failed = run(input + " -o " + quoted(dir.path() / "b.mesh") + " -o " + quoted(dir.path() / "b.node") + " -o " +
                                quoted(blocker / "b.vtu"),
                            dir);
  EXPECT_EQ(failed.exit_code, 5) << failed.out;
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"a.mesh", "a.node", "a.ele", "a.face", "a.msh", "blocker"})) << failed.out;
}

// Inputs without a CDT as given, with --steiner none: exit 4 naming each file and why, nothing
// written. One batch run, two at a time.
TEST(CliMesh, MeshesWithoutCdtExitFourAndWriteNothing) {
  TempDir dir;
  std::vector<fs::path> files{write_schonhardt(dir)};
  // And a copy under another name, so that it is a batch (two files at least), every file failing.
  files.push_back(dir.path() / ("copy_of_" + files.front().filename().string()));
  fs::copy_file(files.front(), files.back());
  std::string inputs;
  for (const fs::path& file : files) inputs += " " + quoted(file);
  const auto out = dir.path() / "out";
  const CliRun r = run("mesh" + inputs + " --steiner none --out-dir " + quoted(out) + " --format vtu,tetgen --threads 2", dir);
  EXPECT_EQ(r.exit_code, 4) << r.out;
  for (const fs::path& file : files) EXPECT_TRUE(r.says("sweepcdt: " + file.string() + ": ")) << file << "\n" << r.out;
  EXPECT_TRUE(r.says("witness vertices")) << r.out;
  EXPECT_TRUE(r.says("0 of " + std::to_string(files.size()) + " files converted")) << r.out;
  EXPECT_TRUE(files_in(out).empty());
}

// Every file of bad/: exit 3 with a message that names the file and the problem; nothing written.
TEST(CliMesh, BadFilesExitThreeNamingTheProblem) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const std::pair<const char*, const char*> expected[] = {{"open_cube.off", "boundary-edge"},
                                                          {"selfintersect_issue945e_ascii.stl", "self-intersection"},
                                                          {"car_open_nonmanifold.drc", "non-manifold-vertex"}};
  std::size_t seen = 0;
  for (const auto& entry : fs::directory_iterator(shared_data() / "bad")) {
    const std::string name = entry.path().filename().string();
    const auto it = std::find_if(std::begin(expected), std::end(expected), [&](const auto& e) { return name == e.first; });
    ASSERT_NE(it, std::end(expected)) << "bad/" << name << " is new: add what its message must say";
    ++seen;
    const CliRun r = run(quoted(entry.path()) + " -o " + quoted(dir.path() / "out.vtu"), dir);
    EXPECT_EQ(r.exit_code, 3) << name << "\n" << r.out;
    EXPECT_TRUE(r.says("sweepcdt: " + entry.path().string() + ": not a closed surface bounding a volume:")) << r.out;
    EXPECT_TRUE(r.says(it->second)) << name << ": expected '" << it->second << "' in\n" << r.out;
    EXPECT_TRUE(files_in(dir.path()).empty()) << name;
  }
  EXPECT_EQ(seen, std::size(expected));
}

TEST(CliMesh, MalformedAndMissingInputsExitThree) {
  TempDir dir;
  const auto bad = dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n");
  const CliRun r = run(quoted(bad) + " -o " + quoted(dir.path() / "out.mesh"), dir);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_TRUE(r.says(bad.string() + ":4:")) << r.out;
  const CliRun missing = run(quoted(dir.path() / "missing.stl") + " -o " + quoted(dir.path() / "out.mesh"), dir);
  EXPECT_EQ(missing.exit_code, 3) << missing.out;
  EXPECT_TRUE(missing.says("missing.stl")) << missing.out;
  EXPECT_EQ(files_in(dir.path()), std::set<std::string>{"bad.off"});
}

// Root may write anywhere, so "unwritable" is a folder that is a file: the writer cannot create its
// temporary file there, and must leave nothing, anywhere.
TEST(CliMesh, UnwritableOutputExitsFiveAndLeavesNothing) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto blocker = dir.write("not_a_folder", "x");
  for (const std::string format : kFormats) {
    const auto out = blocker / ("out" + extension(format));
    const CliRun r = run(quoted(shared_data() / "off/icosahedron.off") + " -o " + quoted(out) + " --format " + format, dir);
    EXPECT_EQ(r.exit_code, 5) << format << "\n" << r.out;
    EXPECT_TRUE(r.says(out.string())) << r.out;
    EXPECT_EQ(files_in(dir.path()), std::set<std::string>{"not_a_folder"}) << format;
  }
  const CliRun batch = run("mesh " + quoted(shared_data() / "off/icosahedron.off") + " --out-dir " + quoted(blocker / "sub"), dir);
  EXPECT_EQ(batch.exit_code, 5) << batch.out;
  EXPECT_TRUE(batch.says("cannot create the output folder")) << batch.out;
}


TEST(CliMesh, SchonhardtPrismHasNoCdtWithoutSteinerPoints) {
  TempDir dir;
  const auto prism = write_schonhardt(dir);
  const auto out = dir.path() / "prism.mesh";
  const CliRun none = run(quoted(prism) + " -o " + quoted(out) + " --steiner none", dir);
  EXPECT_EQ(none.exit_code, 4) << none.out;
  EXPECT_TRUE(none.says("sweepcdt: " + prism.string() + ": ")) << none.out;
  EXPECT_TRUE(none.says("witness vertices")) << none.out;
  EXPECT_FALSE(fs::exists(out));
  const CliRun with = run(quoted(prism) + " -o " + quoted(out) + " --check", dir);
  ASSERT_EQ(with.exit_code, 0) << with.out;
  EXPECT_TRUE(with.says(", checked (")) << with.out;
  const io::VolumeMesh mesh = io::read_volume_mesh(out);
  EXPECT_GT(mesh.num_points(), 6u) << "Steiner points expected";
  EXPECT_EQ(run("check " + quoted(prism) + " " + quoted(out), dir).exit_code, 0);
}

TEST(CliMesh, EveryAlgorithmGivesTheSameMesh) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto input = quoted(shared_data() / "glb/cubevc.glb");
  std::optional<std::pair<std::vector<double>, std::set<std::vector<uint32_t>>>> first;
  for (const char* algorithm : {"cavity-sweep", "sweep-sphere", "sweep-plane", "giftwrap"}) {
    const auto out = dir.path() / (std::string(algorithm) + ".mesh");
    const CliRun r = run(input + " -o " + quoted(out) + " --algorithm " + algorithm, dir);
    ASSERT_EQ(r.exit_code, 0) << algorithm << "\n" << r.out;
    EXPECT_TRUE(r.says(std::string("(") + algorithm + ",")) << r.out;
    // The same tetrahedra; the algorithms list them in different orders.
    const io::VolumeMesh mesh = io::read_volume_mesh(out);
    std::set<std::vector<uint32_t>> tets;
    for (std::size_t t = 0; t < mesh.num_tetrahedra(); ++t) {
      std::vector<uint32_t> v(mesh.tetrahedra.begin() + 4 * t, mesh.tetrahedra.begin() + 4 * t + 4);
      std::sort(v.begin(), v.end());
      tets.insert(v);
    }
    if (!first) first.emplace(mesh.points, tets);
    EXPECT_EQ(mesh.points, first->first) << algorithm;
    EXPECT_EQ(tets, first->second) << algorithm;
  }
}

TEST(CliMesh, StatsAreJsonWithCountsAndTimes) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto input = shared_data() / "off/icosahedron.off";
  const auto out = dir.path() / "ico.inp";
  const auto stats_file = dir.path() / "stats.json";
  const CliRun r = run(quoted(input) + " -o " + quoted(out) + " --stats " + quoted(stats_file) + " --check --algorithm sweep-plane", dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto json = nlohmann::json::parse(bytes_of(stats_file));
  EXPECT_EQ(json["sweepcdt_version"], SWEEPCDT_VERSION);
  EXPECT_EQ(json["command"], "mesh");
  EXPECT_EQ(json["algorithm"], "sweep-plane");
  EXPECT_EQ(json["steiner"], "auto");
  EXPECT_EQ(json["exit_code"], 0);
  EXPECT_GT(json["peak_memory_bytes"].get<uint64_t>(), 1u << 20);
  ASSERT_EQ(json["files"].size(), 1u);
  const auto& f = json["files"][0];
  const io::VolumeMesh mesh = io::read_volume_mesh(out);
  EXPECT_EQ(f["input"], input.string());
  ASSERT_EQ(f["outputs"].size(), 1u);
  EXPECT_EQ(f["outputs"][0]["file"], out.string());
  EXPECT_EQ(f["outputs"][0]["format"], "inp");
  EXPECT_EQ(f["status"], "ok");
  EXPECT_EQ(f["input_triangles"], 20);
  EXPECT_EQ(f["input_vertices"], 12);
  EXPECT_EQ(f["algorithm"], "sweep-plane");
  EXPECT_EQ(f["steiner_points"], 0);
  EXPECT_EQ(f["tetrahedra"].get<std::size_t>(), mesh.num_tetrahedra());
  EXPECT_EQ(f["boundary_triangles"], 20);
  EXPECT_EQ(f["regions"], 1);
  EXPECT_EQ(f["validated"], true);
  for (const char* phase : {"read", "check", "setup", "build", "finish", "validate", "write", "total"}) {
    ASSERT_TRUE(f["seconds"].contains(phase)) << phase;
    EXPECT_GE(f["seconds"][phase].get<double>(), 0.0) << phase;
  }
  EXPECT_GE(f["seconds"]["total"].get<double>(), f["seconds"]["build"].get<double>());
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"ico.inp", "stats.json"}));  // no temporary left

  // The default, the cavity sweep, says what it did: a convex polyhedron's faces are faces of its
  // convex hull, so all are Delaunay faces and nothing is swept again.
  const CliRun cavity = run(quoted(input) + " -o " + quoted(out) + " --stats " + quoted(stats_file), dir);
  ASSERT_EQ(cavity.exit_code, 0) << cavity.out;
  const auto cavity_file = nlohmann::json::parse(bytes_of(stats_file))["files"][0];
  EXPECT_EQ(cavity_file["algorithm"], "cavity-sweep");
  EXPECT_EQ(cavity_file["missing_constraints"], 0);
  EXPECT_EQ(cavity_file["cavity_tetrahedra"], 0);

  // A failure is recorded too, with its status and message.
  const auto bad = dir.write("open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const CliRun failed = run(quoted(bad) + " -o " + quoted(dir.path() / "open.mesh") + " --stats " + quoted(stats_file), dir);
  EXPECT_EQ(failed.exit_code, 3);
  const auto failure = nlohmann::json::parse(bytes_of(stats_file));
  EXPECT_EQ(failure["exit_code"], 3);
  EXPECT_EQ(failure["files"][0]["status"], "bad-input");
  EXPECT_NE(failure["files"][0]["message"].get<std::string>().find("boundary-edge"), std::string::npos);
  EXPECT_FALSE(failure["files"][0].contains("tetrahedra"));
}

}  // namespace
}  // namespace sweepcdt::cli::testing
