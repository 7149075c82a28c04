// `sweepcdt check INPUT OUTPUT`: accepts what `sweepcdt` wrote, rejects (exit 6) meshes that are
// not the CDT — a tetrahedron removed, a vertex moved, a Steiner point moved by one ulp, a flip that
// keeps a valid tetrahedralization but breaks the Delaunay property, boundary triangles flipped,
// mistagged or missing, points no tetrahedron uses — and says why; with --facets coplanar, against
// the polygons of coplanar input triangles.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "sweepcdt/io/volume_mesh.h"
#include "surface_builders.h"
#include "tamper_mesh.h"
#include "sweepcdt/io/write_surface.h"
#include "sweepcdt/predicates.h"
#include "sweepcdt/steiner_point.h"
#include "test_shapes.h"

namespace sweepcdt::cli::testing {
namespace {

using io::testing::flip_one_pair;

// Meshes `input` into `output` with the CLI (and `options`) and reads the result back.
io::VolumeMesh make_mesh(const fs::path& input, const fs::path& output, const TempDir& dir, const std::string& options = "") {
  const CliRun r = run(quoted(input) + " -o " + quoted(output) + " " + options, dir);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  return io::read_volume_mesh(output);
}

CliRun check(const fs::path& input, const fs::path& output, const TempDir& dir, const std::string& options = "") {
  return run("check " + quoted(input) + " " + quoted(output) + " " + options, dir);
}

// `check --facets coplanar` of `mesh` written without face ids (as a triangles-made mesh, or one
// under a later perturbation order, would pass as coplanar but for them).
CliRun check_untagged_as_coplanar(const fs::path& input, io::VolumeMesh mesh, const TempDir& dir) {
  mesh.boundary_tags.assign(mesh.num_boundary(), kNone);
  const auto untagged = dir.path() / "untagged.mesh";
  io::write_volume_mesh(untagged, mesh, io::MeshFormat::Medit);
  return check(input, untagged, dir, "--facets coplanar");
}

TEST(CliCheck, AcceptsWhatWasWrittenAndRejectsTamperedMeshes) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto input = shared_data() / "glb/moon.glb";
  const auto good = dir.path() / "moon.mesh";
  const io::VolumeMesh mesh = make_mesh(input, good, dir);
  const CliRun ok = check(input, good, dir);
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_TRUE(ok.says("moon.mesh: " + std::to_string(mesh.num_tetrahedra()) + " tetrahedra, 2502 vertices (0 Steiner points)")) << ok.out;
  EXPECT_TRUE(ok.says("every interior facet locally Delaunay")) << ok.out;
  EXPECT_TRUE(ok.says("the file's boundary triangles are those, oriented outward, tagged")) << ok.out;

  const auto tampered = dir.path() / "tampered.mesh";
  {
    io::VolumeMesh m = mesh;
    m.tetrahedra.resize(m.tetrahedra.size() - 4);
    if (!m.regions.empty()) m.regions.pop_back();
    io::write_volume_mesh(tampered, m, io::MeshFormat::Medit);
    const CliRun r = check(input, tampered, dir);
    EXPECT_EQ(r.exit_code, 6) << r.out;
    EXPECT_TRUE(r.says("tampered.mesh is not the CDT of " + input.string())) << r.out;
  }
  {
    io::VolumeMesh m = mesh;
    m.points[3 * 7 + 1] += 1e-3;
    io::write_volume_mesh(tampered, m, io::MeshFormat::Medit);
    const CliRun r = check(input, tampered, dir);
    EXPECT_EQ(r.exit_code, 6) << r.out;
    EXPECT_TRUE(r.says("vertex 7 is (")) << r.out;
  }
  {
    io::VolumeMesh m = mesh;
    ASSERT_TRUE(flip_one_pair(m));
    io::write_volume_mesh(tampered, m, io::MeshFormat::Medit);
    const CliRun r = check(input, tampered, dir);
    EXPECT_EQ(r.exit_code, 6) << r.out;
    EXPECT_TRUE(r.says("locally-delaunay")) << r.out;
  }
  // What solvers read as the boundary: orientation, tags, completeness.
  {
    io::VolumeMesh m = mesh;
    ASSERT_GT(m.num_boundary(), 10u);
    std::swap(m.boundary[3 * 5 + 1], m.boundary[3 * 5 + 2]);
    m.boundary_tags[9] = m.boundary_tags[9] == 0 ? 1 : 0;
    m.boundary.resize(m.boundary.size() - 3);
    m.boundary_tags.pop_back();
    io::write_volume_mesh(tampered, m, io::MeshFormat::Gmsh41);
    const CliRun r = check(input, tampered, dir);
    EXPECT_EQ(r.exit_code, 6) << r.out;
    EXPECT_TRUE(r.says("the file's boundary triangle 5 (")) << r.out;
    EXPECT_TRUE(r.says("is oriented inward")) << r.out;
    EXPECT_TRUE(r.says("the file's boundary triangle 9 (")) << r.out;
    EXPECT_TRUE(r.says("but lies on input triangle")) << r.out;
    EXPECT_TRUE(r.says("1 boundary facets of the tetrahedra are missing from the file's boundary triangles")) << r.out;
  }
  // Another surface's mesh.
  const CliRun other = check(shared_data() / "off/icosahedron.off", good, dir);
  EXPECT_EQ(other.exit_code, 6) << other.out;
  // Unreadable mesh: exit 3.
  const auto junk = dir.write("junk.mesh", "not a mesh\n");
  const CliRun unreadable = check(input, junk, dir);
  EXPECT_EQ(unreadable.exit_code, 3) << unreadable.out;
  EXPECT_TRUE(unreadable.says(junk.string())) << unreadable.out;
}

// With Steiner points, each must be exactly a point cdt() can make on an input edge: the rounded
// a + t (b - a) of two neighbouring points on it (sweepcdt/steiner_point.h).
TEST(CliCheck, SteinerPointsMustBeTheSplitPointsCdtMakes) {
  TempDir dir;
  const auto input = write_schonhardt(dir, "prism.off");
  const auto good = dir.path() / "prism.vtu";
  const io::VolumeMesh mesh = make_mesh(input, good, dir);
  ASSERT_GT(mesh.num_points(), 6u);
  const CliRun ok = check(input, good, dir);
  ASSERT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_TRUE(ok.says("(" + std::to_string(mesh.num_points() - 6) + " Steiner points, ")) << ok.out;

  io::VolumeMesh m = mesh;
  // The first Steiner point moved off its edge by far more than rounding (one ulp along the edge
  // could still be the rounding of another point of it: sweepcdt/steiner_point.h).
  m.points[3 * 6] += 1e-9, m.points[3 * 6 + 1] -= 2e-9, m.points[3 * 6 + 2] += 3e-9;
  const auto tampered = dir.path() / "tampered.vtu";
  io::write_volume_mesh(tampered, m, io::MeshFormat::Vtu);
  const CliRun r = check(input, tampered, dir);
  EXPECT_EQ(r.exit_code, 6) << r.out;
  EXPECT_TRUE(r.says("Steiner point 6 (")) << r.out;
  EXPECT_TRUE(r.says("is not a rounded point of the segment of a facet's boundary edge, nor between two points of one facet")) << r.out;
}

// A box with a box-shaped cavity (given outward: the importer reverses it) and a body inside the
// cavity, as dir/nested.stl.
fs::path write_nested_boxes(const TempDir& dir) {
  io::Soup soup;
  io::testing::add_box(soup, {0, 0, 0}, {12, 11, 10});
  io::testing::add_box(soup, {2, 3, 2}, {9, 8, 7});
  io::testing::add_box(soup, {4, 5, 3}, {6, 6, 5});
  const auto input = dir.path() / "nested.stl";
  io::write_surface(input, soup, io::Format::StlBinary);
  return input;
}

// Nested shells: two regions, boundary triangles facing both ways; check must accept it.
TEST(CliCheck, CavityAndNestedBody) {
  TempDir dir;
  const auto input = write_nested_boxes(dir);
  const auto output = dir.path() / "nested.msh";
  const CliRun r = run(quoted(input) + " -o " + quoted(output) + " --stats " + quoted(dir.path() / "s.json"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const CliRun ok = check(input, output, dir);
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  const auto stats = nlohmann::json::parse(bytes_of(dir.path() / "s.json"))["files"][0];
  EXPECT_EQ(stats["input_triangles"], 36);
  EXPECT_EQ(stats["regions"], 2) << "the shell between box and cavity, and the body inside";
  // Each Steiner point on a closed triangulated surface adds two triangles to its 36.
  EXPECT_EQ(stats["boundary_triangles"], 36 + 2 * stats["steiner_points"].get<int>());
  EXPECT_TRUE(ok.says("valid: input vertices identical; " + std::to_string(stats["boundary_triangles"].get<int>()) + " boundary triangles")) << ok.out;
}

// Paper §6: a grid box, every unit square split along (1, 1), has no CDT under the vertex-id
// perturbation but has one under a later order (the lexicographic one, order 2). `--steiner none`
// meshes it exactly; the summary and --stats say which order; check finds the same order and
// validates under it. The cube of cube_att.drc (Draco sample) likewise, under order 1. So does
// check --facets coplanar, against the boundary pieces: the same tetrahedra are a CDT of the
// coplanar polygons (face ids left out: they name triangles). Meshed with --facets coplanar, these
// boxes get their CDT under the vertex-id order, so this is how that path of check is reached.
TEST(CliCheck, MeshesMadeUnderALaterPerturbationOrder) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto grid = dir.path() / "grid.off";
  io::write_surface(grid, fixtures::grid_box_surface(2), io::Format::Off);
  const std::vector<std::tuple<fs::path, int, std::string>> cases{{grid, 2, "coordinates, lexicographically"},
                                                                  {shared_data() / "drc/cube_att.drc", 1, "most constrained vertices first"}};
  for (const auto& [input, order, name] : cases) {
    const auto output = dir.path() / (input.stem().string() + ".mesh");
    const auto stats_file = dir.path() / "s.json";
    const CliRun r = run(quoted(input) + " --steiner none --facets triangles -o " + quoted(output) + " --stats " + quoted(stats_file), dir);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_TRUE(r.says("0 Steiner points, perturbation order " + std::to_string(order) + " (" + name + ")")) << r.out;
    const auto stats = nlohmann::json::parse(bytes_of(stats_file))["files"][0];
    EXPECT_EQ(stats["perturbation_order"], order) << input;
    EXPECT_GT(stats["perturbation_orders"].get<int>(), 1) << input;
    EXPECT_EQ(stats["steiner_points"], 0) << input;
    const CliRun ok = check(input, output, dir, "--facets triangles");
    EXPECT_EQ(ok.exit_code, 0) << ok.out;
    EXPECT_TRUE(ok.says("every interior facet locally Delaunay\n       under perturbation order " + std::to_string(order) + " (" + name)) << ok.out;
    const CliRun coplanar = check_untagged_as_coplanar(input, io::read_volume_mesh(output), dir);
    EXPECT_EQ(coplanar.exit_code, 0) << coplanar.out;
    EXPECT_TRUE(coplanar.says("coplanar facets, tiling them")) << coplanar.out;
    EXPECT_TRUE(coplanar.says("under perturbation order " + std::to_string(order) + " (" + name)) << coplanar.out;
  }
}

// A run that finds no CDT says how many orders it tried, in --stats too; Schönhardt's prism has no
// exact tie, so one.
TEST(CliCheck, NoCdtReportsThePerturbationOrdersTried) {
  TempDir dir;
  const auto prism = write_schonhardt(dir);
  const auto stats_file = dir.path() / "s.json";
  const CliRun r = run(quoted(prism) + " --steiner none -o " + quoted(dir.path() / "p.mesh") + " --stats " + quoted(stats_file), dir);
  EXPECT_EQ(r.exit_code, 4) << r.out;
  EXPECT_EQ(nlohmann::json::parse(bytes_of(stats_file))["files"][0]["perturbation_orders"], 1);
}

// Tetrahedra on the wrong side of the surface: the nested boxes' cavity (between its walls and the
// body inside it) meshed instead of the material, over the same points. Each boundary triangle is a
// piece of an input triangle, but with its tetrahedron outside.
TEST(CliCheck, TetrahedraOutsideTheSurfaceAreRejected) {
  TempDir dir;
  const auto input = write_nested_boxes(dir);
  io::Soup soup;
  io::testing::add_box(soup, {2, 3, 2}, {9, 8, 7});
  io::testing::add_box(soup, {4, 5, 3}, {6, 6, 5});
  const auto cavity = dir.path() / "cavity.stl";
  io::write_surface(cavity, soup, io::Format::StlBinary);
  const io::VolumeMesh material = make_mesh(input, dir.path() / "material.mesh", dir, "--steiner none");
  const io::VolumeMesh outside = make_mesh(cavity, dir.path() / "outside.mesh", dir, "--steiner none");
  std::map<std::array<double, 3>, uint32_t> id;  // the input's point ids
  for (uint32_t v = 0; v < material.num_points(); ++v) id[{material.points[3 * v], material.points[3 * v + 1], material.points[3 * v + 2]}] = v;
  io::VolumeMesh m = material;
  m.tetrahedra.clear();
  for (uint32_t v : outside.tetrahedra) {
    const auto it = id.find({outside.points[3 * v], outside.points[3 * v + 1], outside.points[3 * v + 2]});
    ASSERT_NE(it, id.end());
    m.tetrahedra.push_back(it->second);
  }
  m.regions.assign(m.num_tetrahedra(), 1);
  m.boundary.clear();
  m.boundary_tags.clear();
  const auto tampered = dir.path() / "tampered.mesh";
  io::write_volume_mesh(tampered, m, io::MeshFormat::Medit);
  for (const char* facets : {"--facets triangles", "--facets coplanar"}) {
    const CliRun r = check(input, tampered, dir, facets);
    EXPECT_EQ(r.exit_code, 6) << r.out;
    EXPECT_TRUE(r.says("has its tetrahedron on the outside of the surface")) << facets << "\n" << r.out;
    EXPECT_FALSE(r.says("check it with --facets coplanar")) << facets << "\n" << r.out;
  }
}

// --facets coplanar: each facet's boundary triangles tile the polygon of its coplanar input
// triangles and carry its first triangle as face id. check --facets coplanar accepts such meshes,
// with Steiner points on facet boundaries and inside facets (t13, torus) and without (cubevc, a
// cube with CAD noise in ten facets; the nested boxes, whose cavity's facets have the material on
// their negative side; a cube whose file gives one triangle of a face reversed, which the importer
// notates so). Checked as triangles they fail, and the message says how to check them.
TEST(CliCheck, CoplanarFacetMeshesPassWithFacetsCoplanar) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  io::Soup reversed = io::testing::cube_soup();
  std::swap(reversed.triangles[1], reversed.triangles[2]);
  const auto reversed_file = dir.path() / "reversed.off";
  io::write_surface(reversed_file, reversed, io::Format::Off);
  const std::pair<fs::path, bool> cases[] = {{shared_data() / "stl_ascii/t13_data_ascii.stl", true},
                                             {shared_data() / "stl_binary/torus.stl", true},
                                             {shared_data() / "glb/cubevc.glb", false},
                                             {write_nested_boxes(dir), false},
                                             {reversed_file, false}};
  for (const auto& [input, steiner] : cases) {
    const auto output = dir.path() / (input.stem().string() + ".msh");
    make_mesh(input, output, dir, "--facets coplanar");
    const CliRun ok = check(input, output, dir, "--facets coplanar");
    EXPECT_EQ(ok.exit_code, 0) << ok.out;
    EXPECT_TRUE(ok.says("coplanar facets, tiling them;")) << ok.out;
    EXPECT_TRUE(ok.says("tagged with their facet's first triangle;")) << ok.out;
    EXPECT_EQ(ok.says(" exactly in the plane of their facet, the others rounded split points"), steiner) << ok.out;
    const CliRun as_triangles = check(input, output, dir, "--facets triangles");
    EXPECT_EQ(as_triangles.exit_code, 6) << as_triangles.out;
    EXPECT_TRUE(as_triangles.says("has the right boundary for a mesh made with --facets coplanar")) << as_triangles.out;
    EXPECT_TRUE(as_triangles.says("check it with --facets coplanar")) << as_triangles.out;
  }
}

// What --facets coplanar checks, tampered with on t13 (Steiner points on facet boundaries and inside
// facets): points, tetrahedra, the file's boundary triangles and face ids, and points no
// tetrahedron uses (a facet with a point that is not a vertex of its patch is not tiled by it).
TEST(CliCheck, CoplanarCheckRejectsTamperedMeshes) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto input = shared_data() / "stl_ascii/t13_data_ascii.stl";
  const auto good = dir.path() / "t13.mesh";
  const io::VolumeMesh mesh = make_mesh(input, good, dir, "--facets coplanar");
  const uint32_t n = 788;  // input vertices (MANIFEST.md)
  ASSERT_GT(mesh.num_points(), n);
  ASSERT_EQ(check(input, good, dir, "--facets coplanar").exit_code, 0);
  const auto tampered = dir.path() / "tampered.mesh";
  const auto rejects = [&](const io::VolumeMesh& m, const std::vector<std::string>& says) {
    io::write_volume_mesh(tampered, m, io::MeshFormat::Medit);
    const CliRun r = check(input, tampered, dir, "--facets coplanar");
    EXPECT_EQ(r.exit_code, 6) << r.out;
    for (const auto& text : says) EXPECT_TRUE(r.says(text)) << "missing '" << text << "' in\n" << r.out;
  };
  {
    io::VolumeMesh m = mesh;
    m.points[3 * 5] += 1e-3;
    rejects(m, {"vertex 5 is ("});
  }
  {
    io::VolumeMesh m = mesh;
    m.points[3 * n] += 1e-9, m.points[3 * n + 1] -= 2e-9, m.points[3 * n + 2] += 3e-9;  // off its edge, not along it
    rejects(m, {"Steiner point " + std::to_string(n) + " (", "is not a rounded point of the segment of a facet's boundary edge, nor between two points of one facet"});
  }
  {
    io::VolumeMesh m = mesh;
    m.tetrahedra.erase(m.tetrahedra.begin(), m.tetrahedra.begin() + 4);
    m.regions.erase(m.regions.begin());
    rejects(m, {"tampered.mesh is not the CDT of " + input.string()});
  }
  // The file's boundary: a triangle turned inward, and a face id that names another triangle than
  // its facet's first (on the facet with the most boundary triangles: many input triangles).
  {
    io::VolumeMesh m = mesh;
    std::swap(m.boundary[1], m.boundary[2]);
    std::map<uint32_t, std::size_t> pieces;
    for (uint32_t tag : m.boundary_tags) ++pieces[tag];
    const uint32_t face_id = std::max_element(pieces.begin(), pieces.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
    const std::size_t k = std::find(m.boundary_tags.begin(), m.boundary_tags.end(), face_id) - m.boundary_tags.begin();
    m.boundary_tags[k] = face_id + 1;
    rejects(m, {"the file's boundary triangle 0 (", "is oriented inward",
                "the file's boundary triangle " + std::to_string(k) + " (",
                "is tagged " + std::to_string(face_id + 1) + " but lies on the coplanar facet of input triangles " + std::to_string(face_id) + ", "});
  }
  // A split point that no tetrahedron uses, on a facet boundary edge (its two boundary triangles
  // have different face ids) or on an edge inside a facet (the same face id).
  std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> face_ids_at;  // boundary edge -> face ids beside it
  for (std::size_t k = 0; k < mesh.num_boundary(); ++k)
    for (int i = 0; i < 3; ++i)
      face_ids_at[std::minmax(mesh.boundary[3 * k + i], mesh.boundary[3 * k + (i + 1) % 3])].push_back(mesh.boundary_tags[k]);
  for (const bool ridge : {true, false}) {
    const auto it = std::find_if(face_ids_at.begin(), face_ids_at.end(), [&](const auto& e) {
      return e.first.second < n && e.second.size() == 2 && (e.second[0] != e.second[1]) == ridge;
    });
    ASSERT_NE(it, face_ids_at.end());
    io::VolumeMesh m = mesh;
    double x[3];
    const auto [a, b] = it->first;
    point_on_segment(&m.points[3 * a], &m.points[3 * b], 0.5, x);
    m.points.insert(m.points.end(), x, x + 3);
    const std::string s = std::to_string(mesh.num_points());
    if (ridge)
      rejects(m, {"Steiner point " + s + " lies on ", " but is a vertex of none of its boundary triangles", "of the boundary of",
                  "is an edge of none of its boundary triangles", "edge (" + std::to_string(a) + " " + std::to_string(b) + ") of the boundary triangles on",
                  "bounds their patch but is no piece of the facet's boundary"});
    else
      rejects(m, {"Steiner point " + s + " lies on the coplanar facet of input triangles", " but is a vertex of none of its boundary triangles"});
  }
}

// A mesh made with --facets triangles is a CDT of the coplanar facets too: its pieces tile them, its
// Steiner points on edges inside a facet are points of that facet, and the same points and surface
// make the same CDT. But its face ids name input triangles, not facets: check --facets coplanar
// rejects it for those alone, and accepts it from a file without face ids.
TEST(CliCheck, TrianglesMeshCheckedAsCoplanarDiffersInFaceIdsOnly) {
  SWEEPCDT_REQUIRE_SHARED_DATA();
  TempDir dir;
  const auto input = shared_data() / "glb/cubevc.glb";
  const auto tagged = dir.path() / "cubevc.mesh";
  io::VolumeMesh mesh = make_mesh(input, tagged, dir, "--facets triangles");
  ASSERT_GT(mesh.num_points(), 26u) << "Steiner points on edges inside the cube's faces";
  const CliRun r = check(input, tagged, dir, "--facets coplanar");
  EXPECT_EQ(r.exit_code, 6) << r.out;
  EXPECT_TRUE(r.says("but lies on the coplanar facet of input triangles")) << r.out;
  EXPECT_TRUE(r.says("is the CDT of the input triangles, each a facet of its own")) << r.out;
  EXPECT_TRUE(r.says("check it with --facets triangles")) << r.out;
  EXPECT_FALSE(r.says(": Steiner point")) << r.out;
  EXPECT_FALSE(r.says("edge (")) << r.out;

  const CliRun ok = check_untagged_as_coplanar(input, mesh, dir);
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_TRUE(ok.says("the file's boundary triangles are those, oriented outward (the format has no tags)")) << ok.out;
}

}  // namespace
}  // namespace sweepcdt::cli::testing
