// Volume-mesh files without a CDT: atomic writes (nothing half-written, nothing left behind), format
// names, and the readers' answers to malformed and hostile files (InputError with file and line).
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "sweepcdt/io/volume_mesh.h"
#include "volume_mesh_formats.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io {
namespace {

using testing::TempDir;

// One positive tetrahedron (sweepcdt's orientation) with its four outward faces.
VolumeMesh unit_tetrahedron() {
  VolumeMesh m;
  m.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.num_input_points = 4;
  m.tetrahedra = {0, 1, 3, 2};  // orient(0, 1, 3, 2) > 0: 2 lies below (0, 1, 3) seen counterclockwise
  m.regions = {0};
  m.boundary = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  m.boundary_tags = {0, 1, 2, 3};
  return m;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> listing(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A triangulation built by hand (no neighbours: volume_mesh_of pairs them) over a convex-hull PLC
// whose only constraints are two of the four faces: those carry their tags, the hull faces none.
TEST(VolumeMeshOf, HandBuiltTriangulationWithoutNeighbours) {
  Triangulation<3> tri;
  tri.points = unit_tetrahedron().points;
  tri.num_input_points = 4;
  tri.simplices = unit_tetrahedron().tetrahedra;
  ASSERT_EQ(predicates::orient<3>({tri.point(0), tri.point(1), tri.point(3), tri.point(2)}), predicates::Sign::Positive);
  Plc<3> plc;
  plc.points = tri.points;
  plc.simplices = {2, 1, 0, 3, 0, 1};  // the faces z = 0 and y = 0, in any vertex order
  plc.tags = {100, 101};
  const VolumeMesh m = volume_mesh_of(tri, plc);
  ASSERT_EQ(m.num_boundary(), 4u);
  EXPECT_EQ(m.regions, std::vector<int32_t>{0});
  int tagged = 0;
  const double centre[3] = {0.25, 0.25, 0.25};
  for (std::size_t b = 0; b < 4; ++b) {
    const uint32_t* f = &m.boundary[3 * b];
    // Counterclockwise seen from outside: the inside (the centre) is on the positive side.
    EXPECT_EQ(predicates::orient<3>({&m.points[3 * f[0]], &m.points[3 * f[1]], &m.points[3 * f[2]], centre}), predicates::Sign::Positive) << b;
    std::array<uint32_t, 3> sorted{f[0], f[1], f[2]};
    std::sort(sorted.begin(), sorted.end());
    const uint32_t expected = sorted == std::array<uint32_t, 3>{0, 1, 2} ? 100 : sorted == std::array<uint32_t, 3>{0, 1, 3} ? 101 : kNone;
    EXPECT_EQ(m.boundary_tags[b], expected) << b;
    tagged += expected != kNone;
  }
  EXPECT_EQ(tagged, 2);
}

const MeshFormat kAll[] = {MeshFormat::Medit, MeshFormat::Vtu, MeshFormat::Gmsh41, MeshFormat::Gmsh22, MeshFormat::TetGen, MeshFormat::Abaqus};

TEST(VolumeMeshFormats, NamesAndExtensions) {
  for (MeshFormat f : kAll) EXPECT_EQ(mesh_format_named(to_string(f)), f);
  EXPECT_EQ(mesh_format_named("msh41"), MeshFormat::Gmsh41);
  EXPECT_EQ(mesh_format_named("node"), MeshFormat::TetGen);
  EXPECT_EQ(mesh_format_named("ele"), MeshFormat::TetGen);
  EXPECT_EQ(mesh_format_named("stl"), std::nullopt);
  EXPECT_EQ(mesh_format_of("a/b.MESH"), MeshFormat::Medit);
  EXPECT_EQ(mesh_format_of("b.vtu"), MeshFormat::Vtu);
  EXPECT_EQ(mesh_format_of("b.msh"), MeshFormat::Gmsh41);
  EXPECT_EQ(mesh_format_of("b.ele"), MeshFormat::TetGen);
  EXPECT_EQ(mesh_format_of("b.face"), MeshFormat::TetGen);
  EXPECT_EQ(mesh_format_of("b.inp"), MeshFormat::Abaqus);
  EXPECT_EQ(mesh_format_of("b.off"), std::nullopt);
  EXPECT_EQ(mesh_format_of("b"), std::nullopt);
}

TEST(VolumeMeshWrite, TetgenWritesThreeFilesFromAnyOfTheirNames) {
  TempDir dir;
  for (const char* name : {"a.node", "b.ele", "c.face", "d"}) {
    write_volume_mesh(dir.path() / name, unit_tetrahedron(), MeshFormat::TetGen);
    const std::string stem = std::filesystem::path(name).stem().string();
    for (const char* ext : {".node", ".ele", ".face"}) EXPECT_TRUE(std::filesystem::exists(dir.path() / (stem + ext))) << stem << ext;
    const VolumeMesh back = read_volume_mesh(dir.path() / stem);  // the stem alone names the set
    EXPECT_EQ(back.tetrahedra, unit_tetrahedron().tetrahedra);
    EXPECT_EQ(back.boundary_tags, unit_tetrahedron().boundary_tags);
  }
  EXPECT_EQ(listing(dir.path()).size(), 12u) << "temporaries left behind";
}

TEST(VolumeMeshWrite, MissingFolderThrowsAndLeavesNothing) {
  TempDir dir;
  for (MeshFormat f : kAll) {
    try {
      write_volume_mesh(dir.path() / "no" / "such" / "out.x", unit_tetrahedron(), f);
      ADD_FAILURE() << to_string(f) << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), InputErrorKind::Unreadable);
      EXPECT_NE(std::string(e.what()).find("out.x"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(listing(dir.path()).empty());
}

// A folder under the target name: nothing is renamed (for TetGen: not even the .node and .ele beside
// the blocked .face), the files that were there are untouched, no temporary is left.
TEST(VolumeMeshWrite, FailureLeavesExistingFilesUntouched) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "m.face");
  const auto old_node = dir.write("m.node", "old node\n");
  try {
    write_volume_mesh(dir.path() / "m.node", unit_tetrahedron(), MeshFormat::TetGen);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), InputErrorKind::Unreadable);
    EXPECT_NE(std::string(e.what()).find("m.face"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(old_node), "old node\n");
  EXPECT_EQ(listing(dir.path()), (std::vector<std::string>{"m.face", "m.node"}));

  std::filesystem::create_directory(dir.path() / "v.vtu");
  EXPECT_THROW(write_volume_mesh(dir.path() / "v.vtu", unit_tetrahedron(), MeshFormat::Vtu), InputError);
  EXPECT_TRUE(std::filesystem::is_directory(dir.path() / "v.vtu"));

  // An inconsistent mesh is refused before anything is written.
  const auto old_mesh = dir.write("x.mesh", "old mesh\n");
  VolumeMesh broken = unit_tetrahedron();
  broken.tetrahedra[2] = 9;
  EXPECT_THROW(write_volume_mesh(old_mesh, broken, MeshFormat::Medit), InputError);
  EXPECT_EQ(slurp(old_mesh), "old mesh\n");
  EXPECT_EQ(listing(dir.path()).size(), 4u);
}

TEST(VolumeMeshWrite, ReplacesAnExistingFileWhole) {
  TempDir dir;
  const auto file = dir.write("r.mesh", std::string(100000, 'x'));
  write_volume_mesh(file, unit_tetrahedron(), MeshFormat::Medit);
  const std::string text = slurp(file);
  EXPECT_EQ(text.rfind("MeshVersionFormatted 2\n", 0), 0u);
  EXPECT_EQ(text.find('x'), std::string::npos);
  EXPECT_EQ(read_volume_mesh(file).points, unit_tetrahedron().points);
}

TEST(VolumeMeshWrite, UntaggedBoundaryAndEmptyMeshRoundTrip) {
  TempDir dir;
  VolumeMesh m = unit_tetrahedron();
  m.boundary_tags = {kNone, 7, kNone, 0};
  m.regions = {41};
  for (MeshFormat f : kAll) {
    SCOPED_TRACE(to_string(f));
    auto name = [&](const std::string& stem) {
      return dir.path() / (stem + "." + (f == MeshFormat::Gmsh22 ? "msh" : f == MeshFormat::TetGen ? "node" : to_string(f)));
    };
    const auto file = name("u");
    write_volume_mesh(file, m, f);
    const VolumeMesh back = read_volume_mesh(file);
    EXPECT_EQ(back.regions, m.regions);
    if (f != MeshFormat::Abaqus) EXPECT_EQ(back.boundary_tags, m.boundary_tags);
    // Points without tetrahedra (gmsh 4.1 then needs a volume entity for them) and nothing at all.
    VolumeMesh points_only;
    points_only.points = m.points;
    points_only.num_input_points = 4;
    const auto points_file = name("p");
    write_volume_mesh(points_file, points_only, f);
    EXPECT_EQ(read_volume_mesh(points_file).points, m.points);
    const auto empty_file = name("e");
    write_volume_mesh(empty_file, VolumeMesh{}, f);
    const VolumeMesh empty = read_volume_mesh(empty_file);
    EXPECT_EQ(empty.num_points() + empty.num_tetrahedra() + empty.num_boundary(), 0u);
  }
}

// A mesh whose files run to megabytes: a grid of k^3 points, six tetrahedra per cell (their
// orientation does not matter to the writers), three regions, a tagged bottom.
VolumeMesh large_grid_mesh() {
  VolumeMesh m;
  const uint32_t k = 32;  // k^3 grid points, six tetrahedra per cell
  const auto id = [&](uint32_t x, uint32_t y, uint32_t z) { return (z * k + y) * k + x; };
  for (uint32_t z = 0; z < k; ++z)
    for (uint32_t y = 0; y < k; ++y)
      for (uint32_t x = 0; x < k; ++x) m.points.insert(m.points.end(), {x * 0.1, y * 0.1 + 1e-9 * x, z * 0.1});
  m.num_input_points = k * k * k / 2;
  for (uint32_t z = 0; z + 1 < k; ++z)
    for (uint32_t y = 0; y + 1 < k; ++y)
      for (uint32_t x = 0; x + 1 < k; ++x)
        for (int t = 0; t < 6; ++t) {
          m.tetrahedra.insert(m.tetrahedra.end(), {id(x, y, z), id(x + 1, y, z + (t & 1)), id(x, y + 1, z + (t >> 1 & 1)), id(x + 1, y + 1, z + 1)});
          m.regions.push_back(t % 3);
        }
  for (uint32_t y = 0; y + 1 < k; ++y)
    for (uint32_t x = 0; x + 1 < k; ++x) {
      m.boundary.insert(m.boundary.end(), {id(x, y, 0), id(x, y + 1, 0), id(x + 1, y, 0)});
      m.boundary_tags.push_back(x % 2 ? kNone : y);
    }
  m.on_triangle.assign(m.num_points(), kNone);
  for (std::size_t i = m.num_input_points; i < m.num_points(); ++i) m.on_triangle[i] = static_cast<uint32_t>(i % 7);
  return m;
}

// A mesh whose files run to megabytes: the writers hand their text to the file a megabyte at a time
// (TextOut::spill), and every file must hold exactly the text the writer makes as one string.
TEST(VolumeMeshWrite, LargeFilesWrittenPieceByPieceHoldTheWholeText) {
  const VolumeMesh m = large_grid_mesh();
  TempDir dir;
  const auto check = [&](const std::filesystem::path& file, const std::string& whole) {
    EXPECT_GT(whole.size(), std::size_t{1} << 20) << file;  // more than one piece
    EXPECT_TRUE(slurp(file) == whole) << file;
  };
  write_volume_mesh(dir.path() / "big.mesh", m, MeshFormat::Medit);
  check(dir.path() / "big.mesh", detail::medit_text(m));
  write_volume_mesh(dir.path() / "big.vtu", m, MeshFormat::Vtu);
  check(dir.path() / "big.vtu", detail::vtu_text(m));
  write_volume_mesh(dir.path() / "big.msh", m, MeshFormat::Gmsh41);
  check(dir.path() / "big.msh", detail::gmsh_text(m, false));
  write_volume_mesh(dir.path() / "big2.msh", m, MeshFormat::Gmsh22);
  check(dir.path() / "big2.msh", detail::gmsh_text(m, true));
  write_volume_mesh(dir.path() / "big.inp", m, MeshFormat::Abaqus);
  check(dir.path() / "big.inp", detail::abaqus_text(m));
  write_volume_mesh(dir.path() / "big.node", m, MeshFormat::TetGen);
  const detail::TetGenFiles tetgen = detail::tetgen_texts(m);
  check(dir.path() / "big.node", tetgen.node);
  check(dir.path() / "big.ele", tetgen.ele);
  EXPECT_TRUE(slurp(dir.path() / "big.face") == tetgen.face);
  EXPECT_EQ(listing(dir.path()).size(), 8u);  // no temporary left
}

// A write that fails in the middle of a file (here the file-size limit, as a full disk would): the
// writer stops there, InputError names the file, and no temporary is left. The limit is the
// process's own for the test's length (SIGXFSZ ignored, so write() fails with EFBIG).
TEST(VolumeMeshWrite, FailureInTheMiddleOfAFileLeavesNothing) {
  const VolumeMesh m = large_grid_mesh();
  TempDir dir;
  struct FileSizeLimit {  // restored however the test ends
    rlimit before{};
    void (*handler)(int) = std::signal(SIGXFSZ, SIG_IGN);
    explicit FileSizeLimit(rlim_t bytes) {
      getrlimit(RLIMIT_FSIZE, &before);
      rlimit small = before;
      small.rlim_cur = bytes;
      setrlimit(RLIMIT_FSIZE, &small);
    }
    ~FileSizeLimit() {
      setrlimit(RLIMIT_FSIZE, &before);
      std::signal(SIGXFSZ, handler);
    }
  } limit(3 << 20);  // past the first pieces, short of each file but TetGen's .node (its .ele fails)
  for (const MeshFormat f : {MeshFormat::Medit, MeshFormat::Vtu, MeshFormat::TetGen}) {
    SCOPED_TRACE(to_string(f));
    const auto file = dir.path() / (std::string("full.") + (f == MeshFormat::TetGen ? "node" : to_string(f)));
    try {
      write_volume_mesh(file, m, f);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("cannot write"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(listing(dir.path()).empty());
  }
}

// Reads `text` as `name`: an InputError of `kind` whose message names the file and says `where`.
void expect_error(const TempDir& dir, const std::string& name, const std::string& text, InputErrorKind kind, const std::string& where) {
  testing::expect_file_error(dir, name, text, kind, where, [](const std::filesystem::path& file) { read_volume_mesh(file); });
}

TEST(VolumeMeshRead, MalformedMedit) {
  TempDir dir;
  const std::string head = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
  expect_error(dir, "a.mesh", head + "Tetrahedra\n1\n1 2 3 5 1\nEnd\n", InputErrorKind::IndexOutOfRange, ":11:");
  expect_error(dir, "b.mesh", head + "Tetrahedra\n99999999999\n1 2 3 4 1\n", InputErrorKind::AbsurdCount, ":10:");
  expect_error(dir, "c.mesh", head + "Tetrahedra\n2\n1 2 3 4 1\n1 2 3 4            \n", InputErrorKind::Truncated, ":13:");  // the end of the file
  expect_error(dir, "d.mesh", "MeshVersionFormatted 2\nDimension 2\n", InputErrorKind::Unsupported, ":2:");
  expect_error(dir, "e.mesh", head + "Hexahedra\n0\n", InputErrorKind::Unsupported, ":9:");
  expect_error(dir, "f.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 nan 0 0\n", InputErrorKind::NonFinite, ":5:");
}

TEST(VolumeMeshRead, MalformedGmsh) {
  TempDir dir;
  expect_error(dir, "a.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", InputErrorKind::Unsupported, ":2:");
  expect_error(dir, "b.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n", InputErrorKind::Unsupported, ":2:");
  expect_error(dir, "c.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n1 4 2 1 1 1 1 1 2\n$EndElements\n",
               InputErrorKind::IndexOutOfRange, ":10:");
  expect_error(dir, "d.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n1 5 2 1 1 1 1 1 1 1 1 1 1\n$EndElements\n",
               InputErrorKind::Unsupported, ":10:");
  expect_error(dir, "e.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4000000000 1 4000000000\n", InputErrorKind::AbsurdCount, ":5:");
  expect_error(dir, "f.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n900000000 0 0 0\n$EndNodes\n", InputErrorKind::Unsupported, "sparse");
  expect_error(dir, "g.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n", InputErrorKind::Truncated, "$EndPhysicalNames");
}

TEST(VolumeMeshRead, MalformedVtu) {
  TempDir dir;
  const std::string head = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n";
  expect_error(dir, "a.vtu", head + "<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">\n<Points>\n<DataArray type=\"Float64\" format=\"binary\">AAAA</DataArray>\n</Points><Cells></Cells></Piece>",
               InputErrorKind::Unsupported, ":6:");
  expect_error(dir, "b.vtu", head + "<Piece NumberOfPoints=\"99999999\" NumberOfCells=\"0\">\n<Points>\n<DataArray type=\"Float64\" format=\"ascii\">0 0 0</DataArray>\n</Points><Cells></Cells></Piece>",
               InputErrorKind::AbsurdCount, ":6:");
  expect_error(dir, "c.vtu",
               head + "<Piece NumberOfPoints=\"1\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float64\" format=\"ascii\">0 0 0</DataArray>\n</Points>\n<Cells>\n"
                      "<DataArray Name=\"connectivity\" format=\"ascii\">0 0 0 7</DataArray>\n<DataArray Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
                      "<DataArray Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells></Piece>",
               InputErrorKind::IndexOutOfRange, ":9:");
}

// Found by fuzz_vtu: no <VTKFile> tag made the compressor lookup read past the end (an exception
// that was no InputError).
TEST(VolumeMeshRead, VtuWithoutVtkFileTag) {
  TempDir dir;
  expect_error(dir, "a.vtu", "<?xml version=\"1.0\"?>\n<VTKFil[ type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece Numb NumberOfCells=\"5\">\n",
               InputErrorKind::Syntax, ":4:");
}

TEST(VolumeMeshRead, MalformedTetgenAndAbaqus) {
  TempDir dir;
  dir.write("t.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  expect_error(dir, "t.ele", "1 4 1\n1 1 2 3 5 1\n", InputErrorKind::IndexOutOfRange, "t.ele:2:");
  expect_error(dir, "t.ele", "1 4 1\n1 0 1 2 3 1\n", InputErrorKind::IndexOutOfRange, "t.ele:2:");  // 1-based ids
  expect_error(dir, "t.ele", "70000000 4 0\n", InputErrorKind::AbsurdCount, "t.ele:1:");
  expect_error(dir, "t.ele", "1 4 1\n1 1 2 3 4 1e300\n", InputErrorKind::Syntax, "t.ele:2:");  // region attribute
  expect_error(dir, "t.node", "1 2 0 0\n1 0 0\n", InputErrorKind::Unsupported, "t.node:1:");
  expect_error(dir, "a.inp", "*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=C3D8\n", InputErrorKind::Unsupported, ":3:");
  expect_error(dir, "b.inp", "*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=C3D4\n1, 1, 1, 1, 2\n", InputErrorKind::IndexOutOfRange, ":4:");
  expect_error(dir, "c.inp", "*NODE\n1, 0, zero, 0\n", InputErrorKind::Syntax, ":2:");
  expect_error(dir, "d.inp", "*NODE\n1, 0, 0, 0\n*SURFACE, NAME=S, TYPE=ELEMENT\n1, S7\n", InputErrorKind::Syntax, ":4:");
  expect_error(dir, "e.unknown", "hello\n", InputErrorKind::UnknownFormat, "");
}

}  // namespace
}  // namespace sweepcdt::io
