// run_job() (plugin/meshlab/job.h), the MeshLab filter's work without MeshLab: a layer's arrays in,
// a volume file and the cut-away layer out, or an error with the faces to select.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "job.h"
#include "surface_builders.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::meshlab {
namespace {

struct TempFile {
  std::filesystem::path path;
  explicit TempFile(const std::string& name) : path(std::filesystem::temp_directory_path() / ("sweepcdt_job_test_" + name)) {}
  ~TempFile() { std::filesystem::remove(path); }
};

JobInput cube_input(const std::string& output) {
  const io::Soup soup = io::testing::cube_soup(0, 2);
  JobInput in;
  in.name = "cube";
  in.points = soup.points;
  in.triangles = soup.triangles;
  in.output = output;
  const Choices c = choices();
  in.algorithm = c.default_algorithm;
  in.steiner = c.default_steiner;
  in.facets = c.default_facets;
  return in;
}

TEST(MeshLabJob, DefaultsAreTheConverters) {
  const Choices c = choices();
  const Options defaults = mesh_defaults();  // the converter's
  EXPECT_EQ(c.algorithms.at(c.default_algorithm), to_string(defaults.algorithm));
  ASSERT_EQ(c.algorithms.size(), std::size(kAlgorithms));
  for (std::size_t a = 0; a < c.algorithms.size(); ++a) EXPECT_EQ(c.algorithms[a], to_string(kAlgorithms[a]));  // the job's index
  EXPECT_EQ(c.default_algorithm, 0) << "the default first";
  EXPECT_EQ(c.facets.at(c.default_facets), defaults.facets == FacetMode::Coplanar ? "coplanar" : "triangles");
  EXPECT_EQ(c.steiner.at(c.default_steiner), defaults.steiner == SteinerMode::Auto ? "auto" : "none");
  EXPECT_EQ(c.facets.at(c.default_facets), "coplanar");  // as `sweepcdt mesh`
}

TEST(MeshLabJob, CubeWritesTheVolumeFileAndTheCutAway) {
  TempFile out("cube.mesh");
  JobInput in = cube_input(out.path.string());
  int last = -1;
  bool monotone = true;
  in.progress = [&](int percent, const char*) {
    monotone = monotone && percent >= last && percent <= 100;
    last = percent;
  };
  in.cut_fraction = 1;  // every tetrahedron: the cut-away is the surface
  const JobResult r = run_job(in);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(monotone);
  EXPECT_EQ(last, 100);
  const io::VolumeMesh mesh = io::read_volume_mesh(out.path);
  EXPECT_GT(mesh.num_tetrahedra(), 0u);
  // Every tetrahedron kept: the layer is the file's boundary (its Triangles), over all its points
  // (a cube's CDT has no interior point; Steiner points lie on the surface).
  const std::size_t b = mesh.num_boundary();
  EXPECT_GE(b, 12u);
  EXPECT_EQ(r.triangles.size() / 3, b);
  EXPECT_EQ(r.points.size() / 3, mesh.num_points());
  EXPECT_EQ(r.quality.size(), b);
  EXPECT_EQ(r.on_cut, std::vector<uint8_t>(b, 0));
  for (double q : r.quality) EXPECT_TRUE(q > 0 && q <= 1) << q;
  ASSERT_GE(r.log.size(), 3u);
  EXPECT_NE(r.log[0].find(std::to_string(mesh.num_tetrahedra()) + " tetrahedra"), std::string::npos) << r.log[0];
}

TEST(MeshLabJob, OpenCubeSelectsTheFacesAtTheHoleAndWritesNothing) {
  TempFile out("open.mesh");
  JobInput in = cube_input(out.path.string());
  in.triangles.resize(33);  // triangle 11 gone
  const JobResult r = run_job(in);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("does not bound a volume"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("3 boundary edges"), std::string::npos) << r.error;
  EXPECT_EQ(r.select.size(), 3u);
  EXPECT_FALSE(r.details.empty());
  EXPECT_FALSE(std::filesystem::exists(out.path));
}

TEST(MeshLabJob, NonFiniteVertexIsNamed) {
  TempFile out("nan.mesh");
  JobInput in = cube_input(out.path.string());
  in.points[3 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
  const JobResult r = run_job(in);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("vertex 5 has a non-finite coordinate"), std::string::npos) << r.error;
  std::vector<uint32_t> expected;
  for (uint32_t t = 0; t < 12; ++t)
    if (in.triangles[3 * t] == 5 || in.triangles[3 * t + 1] == 5 || in.triangles[3 * t + 2] == 5) expected.push_back(t);
  EXPECT_EQ(r.select, expected);
}

TEST(MeshLabJob, BadParametersAreRefusedBeforeAnyWork) {
  TempFile out("bad.mesh");
  JobInput in = cube_input(out.path.string());
  in.output = (std::filesystem::temp_directory_path() / "sweepcdt_job_test.xyz").string();
  EXPECT_NE(run_job(in).error.find("unknown volume mesh extension"), std::string::npos);
  in = cube_input(out.path.string());
  for (const char* snap : {"x", "-1", "0.1", "1e-12abc", ""}) {
    in.snap = snap;
    EXPECT_NE(run_job(in).error.find("snap tolerance"), std::string::npos) << snap;
  }
  in.snap = "1e-12";
  EXPECT_TRUE(run_job(in).ok);
  in.output = "/nonexistent-folder/x.mesh";
  const JobResult r = run_job(in);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("/nonexistent-folder/x.mesh"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace sweepcdt::meshlab
