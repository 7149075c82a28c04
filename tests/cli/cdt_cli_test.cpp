// `sweepcdt cdt FILE -o OUT`: PLC files of dimension 2, 3 and 4 through cdt<D>, written as .node/.ele,
// .simplices or (3D) a volume mesh; the typed failures (bad file, invalid PLC, no CDT, wrong output
// for the dimension) with their exit codes.
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "sweepcdt/io/volume_mesh.h"
#include "sweepcdt/predicates.h"

namespace sweepcdt::cli::testing {
namespace {

// A 4 x 4 square with a diamond-shaped hole (Triangle's hole point eats the diamond's inside).
constexpr const char* kDiamondPoly =
    "8 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 2 1\n6 3 2\n7 2 3\n8 1 2\n"
    "8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n"
    "1\n1 2 2\n";

// The first number of a file (the count in a .node/.ele header).
std::size_t first_count(const fs::path& file) {
  std::ifstream in(file);
  std::size_t n = 0;
  in >> n;
  return n;
}

TEST(CliCdt, TwoDimensionalPolyWithHole) {
  TempDir dir;
  const auto poly = dir.write("diamond.poly", kDiamondPoly);
  const CliRun r = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "d.node") + " --check", dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  // 8 points, a square hull: 10 triangles; the hole takes the diamond's 2.
  EXPECT_EQ(first_count(dir.path() / "d.ele"), 8u);
  EXPECT_EQ(first_count(dir.path() / "d.node"), 8u);
  EXPECT_TRUE(r.says("2D, 8 triangles, checked (cavity-sweep,")) << r.out;  // the cavity sweep serves every D

  const CliRun s = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "d.simplices") + " --algorithm giftwrap", dir);
  ASSERT_EQ(s.exit_code, 0) << s.out;
  std::ifstream in(dir.path() / "d.simplices");
  std::string word;
  int d = 0;
  in >> word >> d;
  EXPECT_EQ(word + " " + std::to_string(d), "simplices 2");

  // Outputs that cannot hold a 2D result, and Steiner points (3D only): usage errors, nothing written.
  const CliRun vtu = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "d.vtu"), dir);
  EXPECT_EQ(vtu.exit_code, 2) << vtu.out;
  EXPECT_TRUE(vtu.says("vtu holds tetrahedra, but the PLC is 2-dimensional")) << vtu.out;
  const CliRun steiner = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "e.node") + " --steiner auto", dir);
  EXPECT_EQ(steiner.exit_code, 2) << steiner.out;
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"diamond.poly", "d.node", "d.ele", "d.simplices"}));
}

// A cube as a TetGen .poly with quadrilateral facets, as .node/.ele and as a volume mesh. Its eight
// corners are cospherical: whether the diagonals the reader splits the squares along admit a CDT
// depends on the vertex order (README, "Exactness"), so Steiner points are asked for.
TEST(CliCdt, ThreeDimensionalPoly) {
  TempDir dir;
  const auto poly = dir.write("cube.poly",
                              "8 3 0 0\n1 0 0 0\n2 2 0 0\n3 2 2 0\n4 0 2 0\n5 0 0 2\n6 2 0 2\n7 2 2 2\n8 0 2 2\n"
                              "6 0\n1\n4 1 2 3 4\n1\n4 5 6 7 8\n1\n4 1 2 6 5\n1\n4 2 3 7 6\n1\n4 3 4 8 7\n1\n4 4 1 5 8\n"
                              "0\n0\n");
  const CliRun r = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "c.node") + " --steiner auto", dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_GE(first_count(dir.path() / "c.node"), 8u);
  EXPECT_TRUE(fs::exists(dir.path() / "c.ele"));
  const CliRun v = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "c.vtu") + " --check --steiner auto", dir);
  ASSERT_EQ(v.exit_code, 0) << v.out;
  const io::VolumeMesh mesh = io::read_volume_mesh(dir.path() / "c.vtu");
  EXPECT_EQ(io::read_volume_mesh(dir.path() / "c.node").tetrahedra, mesh.tetrahedra);
  // The tetrahedra fill the cube: six times their volumes sum to 6 * 8 (exact for these integers).
  double six_volume = 0;
  for (std::size_t t = 0; t < mesh.num_tetrahedra(); ++t) {
    const uint32_t* q = mesh.tetrahedra.data() + 4 * t;
    const auto p = [&](int i) { return mesh.points.data() + 3 * std::size_t{q[i]}; };
    six_volume += std::abs(predicates::orient_value<3>({p(0), p(1), p(2), p(3)}));
  }
  EXPECT_EQ(six_volume, 48.0);
  EXPECT_GE(mesh.num_boundary(), 12u);
}

// Four dimensions: a 4-simplex with a point inside, as .simplices (5 simplices around the point).
TEST(CliCdt, FourDimensionalPlc) {
  TempDir dir;
  const auto plc = dir.write("s.plc", "plc 4\npoints 6\n0 0 0 0\n8 0 0 0\n0 8 0 0\n0 0 8 0\n0 0 0 8\n1 1 1 1\nsimplices 1\n0 1 2 3\n");
  const auto stats = dir.path() / "stats.json";
  const CliRun r = run("cdt " + quoted(plc) + " -o " + quoted(dir.path() / "s.simplices") + " --check --stats " + quoted(stats), dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(r.says("4D, 5 simplices, checked")) << r.out;
  const auto json = nlohmann::json::parse(bytes_of(stats));
  EXPECT_EQ(json["command"], "cdt");
  EXPECT_EQ(json["steiner"], "none");
  EXPECT_EQ(json["files"][0]["dimension"], 4);
  EXPECT_EQ(json["files"][0]["input_vertices"], 6);
  EXPECT_EQ(json["files"][0]["input_simplices"], 1);
  EXPECT_EQ(json["files"][0]["simplices"], 5);
  EXPECT_EQ(json["files"][0]["outputs"][0]["format"], "simplices");
  EXPECT_EQ(json["files"][0]["validated"], true);
  std::ifstream in(dir.path() / "s.simplices");
  std::string word;
  std::size_t d = 0, n = 0, input = 0, s = 0;
  in >> word >> d >> word >> n >> word >> input;
  EXPECT_EQ(d, 4u);
  EXPECT_EQ(n, 6u);
  for (std::size_t i = 0; i < 4 * n; ++i) in >> word;
  in >> word >> s;
  EXPECT_EQ(word, "simplices");
  EXPECT_EQ(s, 5u);
  fs::remove(stats);
  const CliRun node = run("cdt " + quoted(plc) + " -o " + quoted(dir.path() / "s.node"), dir);
  EXPECT_EQ(node.exit_code, 2) << node.out;
  EXPECT_TRUE(node.says("use .simplices")) << node.out;
}

TEST(CliCdt, FailuresHaveTheirExitCodes) {
  TempDir dir;
  const auto out = quoted(dir.path() / "out.simplices");
  // Malformed: exit 3 with file and line.
  const auto bad = dir.write("bad.plc", "plc 2\npoints 2\n0 0\n1 x\nsimplices 0\n");
  const CliRun r = run("cdt " + quoted(bad) + " -o " + out, dir);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_TRUE(r.says(bad.string() + ":4:")) << r.out;
  // Crossing segments: an invalid PLC, exit 3 naming the problem.
  const auto crossing = dir.write("cross.plc", "plc 2\npoints 4\n0 0\n2 2\n0 2\n2 0\nsimplices 2\n0 1\n2 3\n");
  const CliRun c = run("cdt " + quoted(crossing) + " -o " + out, dir);
  EXPECT_EQ(c.exit_code, 3) << c.out;
  EXPECT_TRUE(c.says(crossing.string() + ": invalid PLC")) << c.out;
  // Schönhardt's prism as a .plc with exterior notations: no CDT (4); with Steiner points: one.
  const double pi = 3.14159265358979323846;
  std::string prism = "plc 3\npoints 6\n";
  char buf[128];
  for (int level = 0; level < 2; ++level)
    for (int i = 0; i < 3; ++i) {
      const double angle = 2 * pi * i / 3 + (level ? 0.5 : 0.0);
      std::snprintf(buf, sizeof buf, "%.17g %.17g %d\n", std::cos(angle), std::sin(angle), level);
      prism += buf;
    }
  prism += "simplices 8\n0 2 1 -\n3 4 5 -\n";
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    prism += std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(3 + j) + " -\n" + std::to_string(i) + " " +
             std::to_string(3 + j) + " " + std::to_string(3 + i) + " -\n";
  }
  const auto prism_file = dir.write("prism.plc", prism);
  const CliRun none = run("cdt " + quoted(prism_file) + " -o " + quoted(dir.path() / "p.mesh"), dir);
  EXPECT_EQ(none.exit_code, 4) << none.out;
  EXPECT_TRUE(none.says("witness vertices")) << none.out;
  const CliRun with = run("cdt " + quoted(prism_file) + " -o " + quoted(dir.path() / "p.mesh") + " --steiner auto --check", dir);
  EXPECT_EQ(with.exit_code, 0) << with.out;
  EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"bad.plc", "cross.plc", "prism.plc", "p.mesh"}));
}

// The triangles of a .ele file, each as its sorted vertex ids.
std::set<std::vector<int>> triangles_of(const fs::path& ele) {
  std::ifstream in(ele);
  std::size_t count = 0;
  int per = 0, attributes = 0;
  in >> count >> per >> attributes;
  std::set<std::vector<int>> set;
  for (std::size_t k = 0; k < count; ++k) {
    int index = 0;
    std::vector<int> t(per);
    in >> index;
    for (int& v : t) in >> v;
    for (double skip = 0, a = 0; a < attributes; ++a) in >> skip;
    std::sort(t.begin(), t.end());
    set.insert(t);
  }
  return set;
}

// --delete: a 4 x 4 square whose bottom side has a midpoint (4) and three points inside. Deleting the
// midpoint and one inside point gives the CDT of the square without them, computed from scratch; a
// corner and a missing id are refused (a warning; a usage error). The bottom's two segments carry
// one marker (one facet); without markers each segment would be its own facet and the midpoint a
// corner of both.
TEST(CliCdt, DeleteVertices) {
  TempDir dir;
  const auto poly = dir.write("square.poly",
                              "8 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 2 0\n6 1 1\n7 2 3\n8 3 1\n"
                              "5 1\n1 1 5 7\n2 5 2 7\n3 2 3 8\n4 3 4 8\n5 4 1 8\n0\n");
  const auto without = dir.write("without.poly",
                                 "6 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 3 1\n"
                                 "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  const CliRun r = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "d.node") + " --delete 4,6,0 --check", dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(r.says("vertex 0 kept: vertex 0 cannot be deleted")) << r.out;
  EXPECT_TRUE(r.says("2 of 3 vertices deleted")) << r.out;
  const CliRun ref = run("cdt " + quoted(without) + " -o " + quoted(dir.path() / "w.node"), dir);
  ASSERT_EQ(ref.exit_code, 0) << ref.out;
  EXPECT_EQ(first_count(dir.path() / "d.node"), 6u);
  EXPECT_EQ(triangles_of(dir.path() / "d.ele"), triangles_of(dir.path() / "w.ele"));

  const CliRun missing = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "e.node") + " --delete 8", dir);
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_TRUE(missing.says("--delete: vertex 8 does not exist")) << missing.out;
  const CliRun bad = run("cdt " + quoted(poly) + " -o " + quoted(dir.path() / "e.node") + " --delete 1,x", dir);
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
  EXPECT_FALSE(fs::exists(dir.path() / "e.node"));
}

}  // namespace
}  // namespace sweepcdt::cli::testing
