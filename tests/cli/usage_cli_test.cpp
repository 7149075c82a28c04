// Command-line handling: help, version, unknown commands and options, conflicting or missing
// arguments — exit code 2 with a message and the usage, and nothing written.
#include "cli_run.h"

namespace sweepcdt::cli::testing {
namespace {

const std::string kIcosahedron = std::string(SWEEPCDT_SHARED_DATA) + "/off/icosahedron.off";

TEST(CliUsage, HelpAndVersion) {
  TempDir dir;
  const CliRun help = run("--help", dir);
  EXPECT_EQ(help.exit_code, 0);
  for (const char* text : {"sweepcdt INPUT -o OUTPUT", "sweepcdt mesh INPUT... --out-dir DIR", "sweepcdt check INPUT OUTPUT",
                           "sweepcdt cdt FILE -o OUTPUT", "exit codes:", "130"})
    EXPECT_TRUE(help.says(text)) << "missing '" << text << "' in\n" << help.out;
  EXPECT_EQ(run("help", dir).out, help.out);
  const CliRun mesh_help = run("help mesh", dir);
  EXPECT_EQ(mesh_help.exit_code, 0);
  EXPECT_TRUE(mesh_help.says("--steiner auto|none")) << mesh_help.out;
  EXPECT_EQ(run("mesh --help", dir).out, mesh_help.out);
  EXPECT_TRUE(run("check --help", dir).says("a + t (b - a) rounded coordinate by coordinate for some t in (0, 1)"));
  EXPECT_TRUE(run("check --help", dir).says("[--facets triangles|coplanar]"));
  EXPECT_TRUE(run("check --help", dir).says("polygonal facet, its face id its first triangle's index"));
  EXPECT_TRUE(run("cdt --help", dir).says(".simplices"));
  const CliRun version = run("--version", dir);
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out, "sweepcdt " SWEEPCDT_VERSION "\n");
}

TEST(CliUsage, MistakesExitTwoWithUsageAndWriteNothing) {
  TempDir dir;
  const std::string out = quoted(dir.path() / "out.mesh");
  struct Case {
    std::string args, message;
  } cases[] = {
      {"", "no command or INPUT given"},
      {"frobnicate", "unknown command 'frobnicate'"},
      {"help frobnicate", "no command 'frobnicate'"},
      {kIcosahedron + " -o " + out + " --verbose", "unknown option '--verbose'"},
      {"mesh " + kIcosahedron + " -o " + out + " --algorithm quick", "--algorithm must be"},
      {"mesh " + kIcosahedron + " -o " + out + " --steiner some", "--steiner must be auto or none"},
      {"mesh " + kIcosahedron + " -o " + out + " --facets polygons", "--facets must be"},
      {"mesh " + kIcosahedron + " -o " + out + " --check=yes", "--check takes no value"},
      {"mesh " + kIcosahedron, "give either -o OUTPUT"},
      {"mesh " + kIcosahedron + " -o " + out + " --out-dir " + quoted(dir.path()), "give either -o OUTPUT"},
      {"mesh " + kIcosahedron + " " + kIcosahedron + " -o " + out, "-o takes one INPUT"},
      {"mesh " + kIcosahedron + " -o", "-o needs a value"},
      {"mesh " + kIcosahedron + " -o --quiet", "-o needs a value"},
      {"mesh " + kIcosahedron + " -o " + quoted(dir.path() / "out.xyz"), "cannot tell the format of"},
      {"mesh " + kIcosahedron + " -o " + out + " --format vtu", "looks like mesh but --format says vtu"},
      {"mesh " + kIcosahedron + " -o " + out + " --format obj", "unknown --format 'obj'"},
      {"mesh " + kIcosahedron + " -o " + out + " --format mesh,vtu", "with -o, --format names one format"},
      {"mesh " + kIcosahedron + " -o " + out + " -o " + out, "given twice"},
      {"mesh " + kIcosahedron + " --out-dir " + quoted(dir.path()) + " --format msh,vtu,msh22", "--format msh and msh22 both write .msh files"},
      {"mesh " + kIcosahedron + " --out-dir " + quoted(dir.path()) + " --format vtu,", "unknown --format ''"},
      {"mesh " + kIcosahedron + " --out-dir " + quoted(dir.path()) + " --threads 0", "--threads needs a whole number"},
      {"mesh " + kIcosahedron + " --out-dir " + quoted(dir.path()) + " --threads two", "--threads needs a whole number"},
      {"mesh " + kIcosahedron + " " + kIcosahedron + " --out-dir " + quoted(dir.path()), "would both be written to"},
      {"mesh --out-dir " + quoted(dir.path()), "no INPUT given"},
      {"check " + kIcosahedron, "check needs INPUT (the surface) and OUTPUT"},
      {"check " + kIcosahedron + " " + out + " --facets quads", "--facets must be triangles or coplanar, not 'quads'"},
      {"check " + kIcosahedron + " " + out + " --fast", "unknown option '--fast'"},
      {"cdt x.poly", "no -o OUTPUT given"},
      {"cdt x.poly -o y.txt", "cannot tell the format of 'y.txt'"},
      {"cdt x.poly -o y.node --format ply", "unknown --format 'ply'"},
      {"info", "info needs an INPUT file"},
  };
  for (const Case& c : cases) {
    const CliRun r = run(c.args, dir);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.out;
    EXPECT_TRUE(r.says("sweepcdt: ") && r.says(c.message)) << c.args << ": expected '" << c.message << "' in\n" << r.out;
    EXPECT_TRUE(r.says("usage: sweepcdt")) << c.args << "\n" << r.out;
  }
  EXPECT_TRUE(files_in(dir.path()).empty());
}

TEST(CliUsage, BareInputIsTheMeshCommand) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto out = dir.path() / "ico.vtu";
  const CliRun bare = run(kIcosahedron + " -o " + quoted(out), dir);
  ASSERT_EQ(bare.exit_code, 0) << bare.out;
  const std::string first = bytes_of(out);
  const CliRun explicit_mesh = run("mesh -o " + quoted(out) + " " + kIcosahedron, dir);  // options before INPUT too
  ASSERT_EQ(explicit_mesh.exit_code, 0) << explicit_mesh.out;
  EXPECT_EQ(bytes_of(out), first);
  EXPECT_TRUE(bare.says(kIcosahedron + " -> " + out.string() + ": ")) << bare.out;
  EXPECT_TRUE(bare.says("0 Steiner points (cavity-sweep,")) << bare.out;
  EXPECT_TRUE(run(kIcosahedron + " -o " + quoted(out) + " --quiet", dir).out.empty());
}

}  // namespace
}  // namespace sweepcdt::cli::testing
