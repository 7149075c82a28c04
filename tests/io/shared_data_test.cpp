// Every mesh in shared/data, against the counts of shared/data/MANIFEST.md (computed independently,
// with numpy/scipy and CGAL): triangles, welded and stored vertices, closed, shells, intersections.
// Valid ones become a Plc<3> that passes core's check(); each file under bad/ is rejected with the
// problems MANIFEST names.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "sweepcdt/io/read.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/io/to_plc.h"

namespace sweepcdt::io {
namespace {

namespace fs = std::filesystem;

struct Expected {
  const char* path;
  Format format;
  uint64_t triangles, vertices, vertices_in_file;
  bool closed, manifold;
  uint64_t closed_shells, shells, self_intersections;
  uint64_t boundary_edges, non_manifold_vertices;  // MANIFEST's notes on the bad files
};

// From MANIFEST.md (Verts: welded, in brackets the count stored in the file).
const Expected kManifest[] = {
    {"off/femur.off", Format::Off, 7798, 3897, 3897, true, true, 1, 1, 0, 0, 0},
    {"off/icosahedron.off", Format::Off, 20, 12, 12, true, true, 1, 1, 0, 0, 0},
    {"stl_ascii/gearwheel_ascii.stl", Format::StlAscii, 2444, 1222, 7332, true, true, 1, 1, 0, 0, 0},
    {"stl_ascii/t13_data_ascii.stl", Format::StlAscii, 1580, 788, 4740, true, true, 1, 1, 0, 0, 0},
    {"stl_binary/spot.stl", Format::StlBinary, 5856, 2930, 17568, true, true, 1, 1, 0, 0, 0},
    {"stl_binary/torus.stl", Format::StlBinary, 8700, 4350, 26100, true, true, 1, 1, 0, 0, 0},
    {"stl_binary/thingi_1706459.stl", Format::StlBinary, 33926, 16965, 101778, true, true, 1, 1, 0, 0, 0},
    {"gltf/Box.gltf", Format::Gltf, 12, 8, 24, true, true, 1, 1, 0, 0, 0},
    {"gltf/two_objects_inverse_materials.gltf", Format::Gltf, 92, 50, 264, true, true, 2, 2, 0, 0, 0},
    {"glb/moon.glb", Format::Glb, 5000, 2502, 2551, true, true, 1, 1, 0, 0, 0},
    {"glb/cubevc.glb", Format::Glb, 48, 26, 54, true, true, 1, 1, 0, 0, 0},
    {"drc/cube_att.drc", Format::Draco, 12, 8, 24, true, true, 1, 1, 0, 0, 0},
    {"drc/knot1.drc", Format::Draco, 6400, 3200, 3200, true, true, 1, 1, 0, 0, 0},
    {"bad/open_cube.off", Format::Off, 10, 8, 8, false, true, 0, 1, 0, 4, 0},
    {"bad/selfintersect_issue945e_ascii.stl", Format::StlAscii, 94, 49, 282, true, true, 1, 1, 23, 0, 0},
    {"bad/car_open_nonmanifold.drc", Format::Draco, 1744, 920, 1856, false, false, 4, 9, 331, 80, 2},
};

fs::path shared_data() { return fs::path(SWEEPCDT_SHARED_DATA); }

class SharedMesh : public ::testing::TestWithParam<Expected> {};

TEST_P(SharedMesh, CountsMatchManifestAndValidOnesBecomeACheckedPlc) {
  const Expected& e = GetParam();
  const fs::path file = shared_data() / e.path;
  if (!fs::exists(file)) GTEST_SKIP() << "shared sample missing: " << file << " (CI checks out shared/ beside the project)";

  const Soup soup = read_soup(file);
  EXPECT_EQ(soup.format, e.format);
  EXPECT_EQ(soup.num_triangles(), e.triangles);
  EXPECT_EQ(soup.num_points(), e.vertices_in_file);
  const Surface surface = weld(soup);
  EXPECT_EQ(surface.num_points(), e.vertices);
  const SurfaceReport report = inspect(surface);
  EXPECT_EQ(report.closed, e.closed);
  EXPECT_EQ(report.manifold, e.manifold);
  EXPECT_TRUE(report.oriented);  // every sample is consistently oriented (MANIFEST: Oriented yes)
  EXPECT_EQ(report.shells.size(), e.shells);
  EXPECT_EQ(report.closed_shells(), e.closed_shells);
  // MANIFEST's count includes duplicate faces; none of the samples has any.
  EXPECT_EQ(report.count(SurfaceProblemKind::SelfIntersection) + report.count(SurfaceProblemKind::DuplicateTriangle), e.self_intersections);
  EXPECT_EQ(report.count(SurfaceProblemKind::BoundaryEdge), e.boundary_edges);
  EXPECT_EQ(report.count(SurfaceProblemKind::NonManifoldVertex), e.non_manifold_vertices);

  const bool bad = std::string(e.path).starts_with("bad/");
  EXPECT_EQ(report.valid(), !bad);
  if (bad) {
    try {
      to_plc(surface, report);
      ADD_FAILURE() << "to_plc accepted " << e.path;
    } catch (const SurfaceError& error) {
      EXPECT_EQ(error.count(SurfaceProblemKind::BoundaryEdge), e.boundary_edges);
      EXPECT_EQ(error.count(SurfaceProblemKind::SelfIntersection), e.self_intersections);
      EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << "the message names the file";
    }
    return;
  }
  // All samples are single-level bodies with outward normals (MANIFEST: Vol +): nothing to repair.
  EXPECT_EQ(report.reversed_triangles, 0u);
  EXPECT_EQ(report.nested_shells(), 0u);
  const Plc<3> plc = to_plc(surface, report);
  EXPECT_NO_THROW(check(plc));
  ASSERT_EQ(plc.num_simplices(), e.triangles);
  for (std::size_t t = 0; t < plc.num_simplices(); ++t) {
    EXPECT_EQ(plc.exterior[t], ExteriorSide::Negative);
    EXPECT_EQ(plc.tags[t], t);
  }
}

std::string name_of(const ::testing::TestParamInfo<Expected>& info) {
  std::string s = info.param.path;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(Manifest, SharedMesh, ::testing::ValuesIn(kManifest), name_of);

// Keeps the table above complete: a mesh added to shared/data must get its expected counts here.
TEST(SharedData, EveryMeshFileIsInTheTable) {
  if (!fs::is_directory(shared_data())) GTEST_SKIP() << "shared data missing: " << shared_data();
  std::set<std::string> listed;
  for (const Expected& e : kManifest) listed.insert(e.path);
  for (const auto& entry : fs::recursive_directory_iterator(shared_data())) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext == ".md" || ext == ".json" || ext == ".bin") continue;  // the manifests; glTF's external buffers
    EXPECT_TRUE(listed.count(fs::relative(entry.path(), shared_data()).generic_string())) << entry.path() << " is not in kManifest";
  }
}

}  // namespace
}  // namespace sweepcdt::io
