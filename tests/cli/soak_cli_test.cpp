// A soak run of the whole pipeline (issue 13): perturbed versions of real surfaces through the
// default command — jittered coordinates (faces no longer exactly flat), the thinnest triangles
// flipped (inconsistent orientation), a second copy far away (two bodies). Whatever the input, the
// converter must end with a documented outcome — a mesh that `sweepcdt check` accepts (0), invalid
// input (3) or no CDT within the point budget (4) — never an internal error, a crash or a hang, and
// a failure must leave no output file.
#include <algorithm>
#include <cmath>
#include <random>

#include "cli_run.h"
#include "sweepcdt/io/read.h"

namespace sweepcdt::cli::testing {
namespace {

const char* kSurfaces[] = {"off/icosahedron.off", "drc/cube_att.drc", "glb/cubevc.glb", "stl_ascii/t13_data_ascii.stl",
                           "glb/moon.glb",        "stl_binary/spot.stl"};
const char* kCadParts[] = {"bracket_std.stl", "gear_std.stl", "rotated_box_std.obj"};

double bbox_diagonal(const io::Soup& soup) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t i = 0; i < soup.points.size(); ++i) lo[i % 3] = std::min(lo[i % 3], soup.points[i]), hi[i % 3] = std::max(hi[i % 3], soup.points[i]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

io::Soup jittered(io::Soup soup, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double size = bbox_diagonal(soup) * 1e-12;
  for (double& x : soup.points) x += u(rng) * size;
  return soup;
}

io::Soup thinnest_flipped(io::Soup soup) {
  const auto p = [&](uint32_t v, int k) { return soup.points[3 * std::size_t{v} + k]; };
  std::vector<std::pair<double, std::size_t>> thinness;  // area / longest edge², per triangle
  for (std::size_t t = 0; t < soup.num_triangles(); ++t) {
    const uint32_t* v = &soup.triangles[3 * t];
    double e[3][3], longest = 0;
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) e[i][k] = p(v[(i + 1) % 3], k) - p(v[i], k);
      longest = std::max(longest, e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2]);
    }
    const double area = std::hypot(e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2], e[0][0] * e[1][1] - e[0][1] * e[1][0]);
    thinness.emplace_back(area / longest, t);
  }
  std::sort(thinness.begin(), thinness.end());
  for (std::size_t k = 0; k < std::min<std::size_t>(3, thinness.size()); ++k)
    std::swap(soup.triangles[3 * thinness[k].second + 1], soup.triangles[3 * thinness[k].second + 2]);
  return soup;
}

io::Soup with_copy_far_away(io::Soup soup) {
  const double shift = 10 * bbox_diagonal(soup);
  const uint32_t n = static_cast<uint32_t>(soup.num_points());
  for (uint32_t v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k) soup.points.push_back(soup.points[3 * std::size_t{v} + k] + (k == 0 ? shift : 0));
  const std::size_t m = soup.triangles.size();
  for (std::size_t i = 0; i < m; ++i) soup.triangles.push_back(soup.triangles[i] + n);
  return soup;
}

TEST(CliSoak, PerturbedSurfacesEndWithADocumentedOutcome) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  std::vector<fs::path> inputs;
  for (const char* name : kSurfaces) inputs.push_back(shared_data() / name);
  for (const char* name : kCadParts) inputs.push_back(fs::path(SWEEPCDT_TEST_DATA) / "cad" / name);
  TempDir dir;
  std::mt19937_64 rng(13);
  int outcomes[3] = {0, 0, 0};  // meshed, invalid input, no CDT
  for (const fs::path& input : inputs) {
    ASSERT_TRUE(fs::exists(input)) << input;
    const io::Soup soup = io::read_soup(input);
    const std::pair<std::string, io::Soup> variants[] = {
        {"jittered", jittered(soup, rng)}, {"flipped", thinnest_flipped(soup)}, {"two_bodies", with_copy_far_away(soup)}};
    for (const auto& [kind, variant] : variants) {
      const fs::path surface = dir.path() / (input.stem().string() + "_" + kind + ".off");  // OFF: %.17g, exact
      io::write_surface(surface, variant, io::Format::Off);
      const fs::path output = dir.path() / (input.stem().string() + "_" + kind + ".mesh");
      // A hang guard only (each run takes seconds): a killed run exits 124, which fails below.
      const CliRun r = run(quoted(surface) + " -o " + quoted(output), dir, 600);
      SCOPED_TRACE(surface.filename().string() + ":\n" + r.out);
      EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 3 || r.exit_code == 4) << "exit " << r.exit_code;
      // Two far-apart copies of a valid surface are valid, and each copy meshes alone: they must mesh.
      if (kind == "two_bodies") EXPECT_EQ(r.exit_code, 0);
      EXPECT_FALSE(r.says("internal error"));
      if (r.exit_code != 0) {
        EXPECT_FALSE(fs::exists(output));
        ++outcomes[r.exit_code == 3 ? 1 : 2];
        continue;
      }
      ++outcomes[0];
      const CliRun ok = run("check " + quoted(surface) + " " + quoted(output), dir);
      EXPECT_EQ(ok.exit_code, 0) << ok.out;
    }
  }
  std::printf("  %d meshed and checked, %d invalid input, %d without a CDT within the budget\n", outcomes[0], outcomes[1], outcomes[2]);
}

}  // namespace
}  // namespace sweepcdt::cli::testing
