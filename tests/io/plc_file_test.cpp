// PLC files (issue 6): sweepcdt .plc (any D), Triangle .poly (holes -> exterior notations with
// Triangle's meaning), TetGen .poly/.smesh (facets, facet holes, volume holes, regions), and
// write_triangulation(). Valid files give the expected PLC and a CDT whose area/volume is exact;
// malformed ones an InputError at the right line.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <fstream>
#include <set>
#include <sstream>

#include "external_tools.h"
#include "io_test_util.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/plc_file.h"
#include "sweepcdt/io/volume_mesh.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io {
namespace {

using testing::TempDir;

template <int D>
Plc<D> read_as(const std::filesystem::path& file) {
  AnyPlc any = read_plc_file(file);
  EXPECT_TRUE(std::holds_alternative<Plc<D>>(any)) << file << " read with dimension index " << any.index();
  return std::get<Plc<D>>(std::move(any));
}

void expect_error(const TempDir& dir, const std::string& name, const std::string& text, InputErrorKind kind, const std::string& where) {
  testing::expect_file_error(dir, name, text, kind, where, [](const std::filesystem::path& file) { read_plc_file(file); });
}

mpq_class q(double x) { return mpq_class(x); }

// Twice the area of a 2D triangulation, exactly (every triangle counterclockwise: positive).
mpq_class twice_area(const Triangulation<2>& tri) {
  mpq_class sum = 0;
  for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
    const double *a = tri.point(tri.simplex(t)[0]), *b = tri.point(tri.simplex(t)[1]), *c = tri.point(tri.simplex(t)[2]);
    sum += (q(b[0]) - q(a[0])) * (q(c[1]) - q(a[1])) - (q(b[1]) - q(a[1])) * (q(c[0]) - q(a[0]));
  }
  return sum;
}

// Six times the volume of a 3D triangulation (sweepcdt orientation: det [a-d; b-d; c-d] > 0).
mpq_class six_volume(const Triangulation<3>& tri) {
  mpq_class sum = 0;
  for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
    mpq_class m[3][3];
    const double* d = tri.point(tri.simplex(t)[3]);
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) m[r][k] = q(tri.point(tri.simplex(t)[r])[k]) - q(d[k]);
    sum += m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
  return sum;
}

template <int D>
Triangulation<D> checked_cdt(const Plc<D>& plc) {
  Options options;
  if constexpr (D == 3) options.steiner = SteinerMode::Auto;
  Plc<D> triangulated;
  Triangulation<D> tri = cdt(plc, options, &triangulated);
  const auto report = validate_triangulated(tri, triangulated);
  EXPECT_TRUE(report.ok()) << report.summary();
  return tri;
}

TEST(PlcText, ReadsEveryDimension) {
  TempDir dir;
  const auto file = dir.write("square.plc",
                              "# a unit square, outside notated\nplc 2\npoints 4\n0 0\n1 0\n1 1\n0 1\n"
                              "simplices 4\n0 1 - 10\n1 2 - 11\n2 3 - 12\n3 0 - 13\nseeds 1\n0.5 0.5 7\n");
  const Plc<2> plc = read_as<2>(file);
  EXPECT_EQ(plc.points, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1}));
  EXPECT_EQ(plc.simplices, (std::vector<uint32_t>{0, 1, 1, 2, 2, 3, 3, 0}));
  EXPECT_EQ(plc.exterior, std::vector<ExteriorSide>(4, ExteriorSide::Negative));
  EXPECT_EQ(plc.tags, (std::vector<uint32_t>{10, 11, 12, 13}));
  ASSERT_EQ(plc.region_seeds.size(), 1u);
  EXPECT_EQ(plc.region_seeds[0].region, 7);
  const auto tri = checked_cdt(plc);
  EXPECT_EQ(twice_area(tri), 2);
  EXPECT_EQ(tri.regions, std::vector<int32_t>(tri.num_simplices(), 7));

  // 4D: a simplex's facets without notations (the convex hull), no tags.
  const auto four = dir.write("s.plc", "plc 4\npoints 5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\nsimplices 1\n0 1 2 3\n");
  const Plc<4> p4 = read_as<4>(four);
  EXPECT_EQ(p4.num_points(), 5u);
  EXPECT_TRUE(p4.exterior.empty());
  EXPECT_TRUE(p4.tags.empty());
  EXPECT_EQ(checked_cdt(p4).num_simplices(), 1u);
  const auto five = dir.write("s5.plc", "plc 5\npoints 0\nsimplices 0\n");
  EXPECT_EQ(read_as<5>(five).num_points(), 0u);
}

TEST(PlcText, MalformedFilesNameTheLine) {
  TempDir dir;
  expect_error(dir, "a.plc", "plc 6\n", InputErrorKind::Unsupported, "a.plc:1:");
  expect_error(dir, "b.plc", "plc 2\npoints 2\n0 0\n1            \n", InputErrorKind::Syntax, "b.plc:4:");
  expect_error(dir, "c.plc", "plc 2\npoints 2\n0 0\n1 1\nsimplices 1\n0 2\n", InputErrorKind::IndexOutOfRange, "c.plc:6:");
  expect_error(dir, "d.plc", "plc 2\npoints 2\n0 0\n1 1\nsimplices 1\n0 1 x\n", InputErrorKind::Syntax, "d.plc:6:");
  expect_error(dir, "e.plc", "plc 2\npoints 2\n0 0\n1 1\nsimplices 2\n0 1 + 3\n1 0 +\n", InputErrorKind::Syntax, "e.plc:7:");
  expect_error(dir, "f.plc", "plc 3\npoints 4000000000\n", InputErrorKind::AbsurdCount, "f.plc:2:");
  expect_error(dir, "g.plc", "plc 2\npoints 1\ninf 0\nsimplices 0\n", InputErrorKind::NonFinite, "g.plc:3:");
  expect_error(dir, "h.plc", "plc 2\npoints 1\n0 0\nsimplices 0\nseeds 1\n0 0          \n", InputErrorKind::Syntax, "h.plc:6:");
  expect_error(dir, "i.txt", "hello\n", InputErrorKind::UnknownFormat, "i.txt");
}

// A 4 x 4 square with a 2 x 2 square hole in its middle (Triangle's .poly, 1-based, markers).
const char* kSquareWithHole =
    "8 2 0 1\n1 0 0 1\n2 4 0 1\n3 4 4 1\n4 0 4 1\n5 1 1 2\n6 3 1 2\n7 3 3 2\n8 1 3 2\n"
    "8 1\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n5 5 6 6\n6 6 7 6\n7 7 8 6\n8 8 5 6\n"
    "1\n1 2 2\n";

TEST(TrianglePoly, HoleBecomesExteriorNotation) {
  TempDir dir;
  const Plc<2> plc = read_as<2>(dir.write("ring.poly", kSquareWithHole));
  ASSERT_EQ(plc.num_simplices(), 8u);
  EXPECT_EQ(plc.tags, (std::vector<uint32_t>{5, 5, 5, 5, 6, 6, 6, 6}));
  // Outer square counterclockwise: the domain is on the left (positive) side, the outside negative.
  for (int j = 0; j < 4; ++j) EXPECT_EQ(plc.exterior[j], ExteriorSide::Negative) << j;
  // Inner square counterclockwise too: its left side is the hole.
  for (int j = 4; j < 8; ++j) EXPECT_EQ(plc.exterior[j], ExteriorSide::Positive) << j;
  const auto tri = checked_cdt(plc);
  EXPECT_EQ(twice_area(tri), 2 * (16 - 4));
  const double hole[2] = {2, 2};
  for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
    int inside = 0;
    for (int i = 0; i < 3; ++i)
      inside += predicates::orient<2>({tri.point(tri.simplex(t)[i]), tri.point(tri.simplex(t)[(i + 1) % 3]), hole}) == predicates::Sign::Positive;
    EXPECT_LT(inside, 3) << "triangle " << t << " covers the hole point";
  }
}

TEST(TrianglePoly, ConcavityEatenNodeFileAndRegions) {
  TempDir dir;
  // An L: the notch is eaten from the hull; points in a .node file; two regions split by a segment.
  dir.write("l.node", "# the L\n7 2 0 0\n0 0 0\n1 2 0\n2 2 1\n3 1 1\n4 1 2\n5 0 2\n6 0 1\n");
  const Plc<2> plc = read_as<2>(dir.write("l.poly", "0 2 0 0\n8 0\n0 0 1\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 0\n7 3 6\n0\n2\n1 0.5 0.5 4\n2 0.5 1.5 9 0.1\n"));
  EXPECT_EQ(plc.num_points(), 7u);
  EXPECT_EQ(plc.tags, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(plc.exterior[7], ExteriorSide::None);  // the splitting segment has the domain on both sides
  const auto tri = checked_cdt(plc);
  EXPECT_EQ(twice_area(tri), 2 * 3);
  std::set<int32_t> regions(tri.regions.begin(), tri.regions.end());
  EXPECT_EQ(regions, (std::set<int32_t>{4, 9}));
}

TEST(TrianglePoly, PointSetIsItsConvexHull) {
  TempDir dir;
  const Plc<2> plc = read_as<2>(dir.write("pts.poly", "4 2 0 0\n1 0 0\n2 2 0\n3 0 2\n4 1 1\n0 0\n0\n"));
  EXPECT_TRUE(plc.exterior.empty());
  EXPECT_EQ(twice_area(checked_cdt(plc)), 4);
}

TEST(TrianglePoly, MalformedFilesNameTheLine) {
  TempDir dir;
  expect_error(dir, "a.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 4\n", InputErrorKind::IndexOutOfRange, "a.poly:6:");
  expect_error(dir, "b.poly", "3 2 0 0\n1 0 0\n3 1 0\n                 \n", InputErrorKind::Syntax, "b.poly:3:");
  expect_error(dir, "c.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n1\n1 0.5 0\n", InputErrorKind::BadPolygon, "hole 0");
  // Crossing segments: not a PSLG.
  expect_error(dir, "d.poly", "4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n2 0\n1 1 2\n2 3 4\n", InputErrorKind::BadPolygon, "d.poly");
  expect_error(dir, "e.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n900000000 0\n", InputErrorKind::AbsurdCount, "e.poly:5:");
  expect_error(dir, "f.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n1\n1 0.2 0.2\n", InputErrorKind::BadPolygon, "empty");
  try {  // the error names the missing .node file
    read_plc_file(dir.write("g.poly", "0 2 0 0\n0 0\n"));
    ADD_FAILURE() << "g.poly was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), InputErrorKind::Unreadable);
    EXPECT_NE(std::string(e.what()).find("g.node"), std::string::npos) << e.what();
  }
  // A .node file that also says "0 points" (which would mean "see the .node file") is refused, not
  // followed back to itself until the stack overflows; both dimensions.
  for (const char* dimension : {"2", "3"}) {
    dir.write("h.node", std::string("0 ") + dimension + " 0 0\n");
    try {
      read_plc_file(dir.write("h.poly", std::string("0 ") + dimension + " 0 0\n0 0\n0\n"));
      ADD_FAILURE() << "h.poly was accepted, dimension " << dimension;
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind(), InputErrorKind::Truncated) << e.what();
      EXPECT_NE(std::string(e.what()).find("h.node:1:"), std::string::npos) << e.what();
    }
  }
}

// A 2-cube as six square facets (TetGen .poly, markers 1..6), optionally with a unit cube inside.
std::string cube_poly(bool inner, const std::string& holes, const std::string& regions) {
  std::string s = std::string(inner ? "16" : "8") + " 3 0 0\n";
  const int corners[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}};
  for (int i = 0; i < 8; ++i) s += std::to_string(i + 1) + " " + std::to_string(corners[i][0]) + " " + std::to_string(corners[i][1]) + " " + std::to_string(corners[i][2]) + "\n";
  if (inner)
    for (int i = 0; i < 8; ++i)
      s += std::to_string(i + 9) + " " + std::to_string(0.5 + 0.5 * corners[i][0]) + " " + std::to_string(0.5 + 0.5 * corners[i][1]) + " " + std::to_string(0.5 + 0.5 * corners[i][2]) + "\n";
  const int faces[6][4] = {{1, 2, 3, 4}, {5, 6, 7, 8}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}};
  s += std::to_string(inner ? 12 : 6) + " 1\n";
  for (int shell = 0; shell < (inner ? 2 : 1); ++shell)
    for (int f = 0; f < 6; ++f) {
      s += "1 0 " + std::to_string(shell * 6 + f + 1) + "\n4";
      for (int k = 0; k < 4; ++k) s += " " + std::to_string(faces[f][k] + 8 * shell);
      s += "\n";
    }
  return s + holes + regions;
}

TEST(TetgenPoly, CubeFacetsBecomeTaggedNotatedTriangles) {
  TempDir dir;
  const Plc<3> plc = read_as<3>(dir.write("cube.poly", cube_poly(false, "0\n", "")));
  ASSERT_EQ(plc.num_simplices(), 12u);
  std::multiset<uint32_t> tags(plc.tags.begin(), plc.tags.end());
  for (uint32_t marker = 1; marker <= 6; ++marker) EXPECT_EQ(tags.count(marker), 2u) << marker;
  for (ExteriorSide side : plc.exterior) EXPECT_NE(side, ExteriorSide::None);
  const auto tri = checked_cdt(plc);
  EXPECT_EQ(six_volume(tri), 6 * 8);
}

TEST(TetgenPoly, CavityByHolePointOrSecondRegion) {
  TempDir dir;
  // With a hole point in the inner cube: a cavity.
  const Plc<3> hollow = read_as<3>(dir.write("hollow.poly", cube_poly(true, "1\n1 1 1 1\n", "")));
  const auto tri = checked_cdt(hollow);
  EXPECT_EQ(six_volume(tri), 6 * (8 - 1));
  // Without: two regions, named by the region list.
  const Plc<3> filled = read_as<3>(dir.write("filled.poly", cube_poly(true, "0\n", "2\n1 1 1 1 5 0\n2 0.1 0.1 0.1 3 0\n")));
  const auto both = checked_cdt(filled);
  EXPECT_EQ(six_volume(both), 6 * 8);
  std::set<int32_t> regions(both.regions.begin(), both.regions.end());
  EXPECT_EQ(regions, (std::set<int32_t>{3, 5}));
}

TEST(TetgenPoly, FacetWithHoleAndSmesh) {
  TempDir dir;
  // The top of the 2-cube as a ring (outer square, inner square, facet hole) plus the inner square as
  // its own facet: a closed surface again, the ring's triangles tagged 2, the patch's 7.
  std::string s = "12 3 0 0\n1 0 0 0\n2 2 0 0\n3 2 2 0\n4 0 2 0\n5 0 0 2\n6 2 0 2\n7 2 2 2\n8 0 2 2\n"
                  "9 0.5 0.5 2\n10 1.5 0.5 2\n11 1.5 1.5 2\n12 0.5 1.5 2\n7 1\n"
                  "1 0 1\n4 1 2 3 4\n2 1 2\n4 5 6 7 8\n4 9 10 11 12\n1 1 1 2\n1 0 7\n4 9 10 11 12\n"
                  "1 0 3\n4 1 2 6 5\n1 0 4\n4 2 3 7 6\n1 0 5\n4 3 4 8 7\n1 0 6\n4 4 1 5 8\n0\n";
  const Plc<3> plc = read_as<3>(dir.write("ring.poly", s));
  std::multiset<uint32_t> tags(plc.tags.begin(), plc.tags.end());
  EXPECT_EQ(tags.count(2), 8u);  // a square ring: 8 triangles
  EXPECT_EQ(tags.count(7), 2u);
  EXPECT_EQ(six_volume(checked_cdt(plc)), 6 * 8);

  // .smesh: a tetrahedron's four faces, 0-based, no markers (tags = facet index).
  const Plc<3> tet = read_as<3>(dir.write("t.smesh", "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 0\n3 0 1 2\n3 0 1 3\n3 1 2 3\n3 0 2 3\n0\n0\n"));
  EXPECT_EQ(tet.tags, (std::vector<uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(six_volume(checked_cdt(tet)), 1);
}

TEST(TetgenPoly, MalformedFilesNameTheLine) {
  TempDir dir;
  const std::string nodes = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  expect_error(dir, "a.poly", nodes + "1 0\n1\n3 1 2 5\n", InputErrorKind::IndexOutOfRange, "a.poly:8:");
  expect_error(dir, "b.poly", nodes + "1 0\n1\n4 1 2 3 4\n", InputErrorKind::BadPolygon, "b.poly:7:");  // not planar
  expect_error(dir, "c.smesh", nodes + "2 0\n3 1 2 3\n2 1 2\n", InputErrorKind::BadPolygon, "c.smesh:8:");
  expect_error(dir, "d.poly", nodes + "1 0\n1\n3 1 2\n", InputErrorKind::Syntax, "d.poly:8:");
  // An open surface with a hole point: which side would be eaten?
  expect_error(dir, "e.smesh", nodes + "1 0\n3 1 2 3\n1\n1 0.1 0.1 0.1\n", InputErrorKind::Unsupported, "closed");
  expect_error(dir, "f.smesh", nodes + "4 0\n3 1 2 3\n3 1 2 4\n3 2 3 4\n3 1 3 4\n1\n1 0 0 0\n", InputErrorKind::BadPolygon, "hole 0");
}

TEST(WriteTriangulation, NodeEleAndSimplices) {
  TempDir dir;
  const Plc<3> plc = read_as<3>(dir.write("cube.poly", cube_poly(true, "0\n", "")));
  const auto tri = checked_cdt(plc);
  write_triangulation(dir.path() / "c.ele", tri, TriangulationFormat::NodeEle);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "c.node"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "c.face"));
  const VolumeMesh back = read_volume_mesh(dir.path() / "c.ele");  // our TetGen reader: same tetrahedra
  EXPECT_EQ(back.tetrahedra, tri.simplices);
  EXPECT_EQ(back.regions, tri.regions);
  EXPECT_EQ(back.points, tri.points);
  // Orientation as TetGen defines it, read from the file's text (our reader undoes the writer's
  // swap, so the round trip alone cannot tell; tetgen -r reorients silently): every tetrahedron
  // a b c d as listed has det[b - a, c - a, d - a] > 0, exactly (mpq).
  {
    std::ifstream ele(dir.path() / "c.ele");
    std::size_t count = 0, corners = 0, attributes = 0;
    ele >> count >> corners >> attributes;
    ASSERT_EQ(count, tri.num_simplices());
    for (std::size_t t = 0; t < count; ++t) {
      std::size_t id = 0, v[4], region = 0;
      ele >> id >> v[0] >> v[1] >> v[2] >> v[3];
      if (attributes) ele >> region;
      mpq_class m[3][3];
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) m[r][k] = mpq_class(tri.point(static_cast<uint32_t>(v[r + 1] - 1))[k]) - mpq_class(tri.point(static_cast<uint32_t>(v[0] - 1))[k]);
      const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      EXPECT_GT(det, 0) << "tetrahedron " << id;
    }
  }
  if (testing::require_tool("tetgen", "tetgen")) {
    const auto run = testing::run_tool("timeout 60 tetgen -rCNEF " + testing::quoted(dir.path() / "c"));
    EXPECT_NE(run.output.find("the mesh appears to be consistent"), std::string::npos) << run.output;
  }

  const Plc<2> ring = read_as<2>(dir.write("ring.poly", kSquareWithHole));
  const auto tri2 = checked_cdt(ring);
  write_triangulation(dir.path() / "r.simplices", tri2, TriangulationFormat::Simplices);
  std::ifstream in(dir.path() / "r.simplices");
  std::string word;
  int d = 0;
  std::size_t n = 0, input = 0, s = 0;
  in >> word >> d;
  EXPECT_EQ(word, "simplices");
  EXPECT_EQ(d, 2);
  in >> word >> n >> word >> input;
  EXPECT_EQ(n, tri2.num_points());
  EXPECT_EQ(input, tri2.num_input_points);
  std::vector<double> points(2 * n);
  for (double& x : points) in >> x;
  EXPECT_EQ(points, tri2.points);
  in >> word >> s;
  ASSERT_EQ(s, tri2.num_simplices());
  for (std::size_t t = 0; t < s; ++t) {
    uint32_t v[3];
    int32_t region;
    in >> v[0] >> v[1] >> v[2] >> region;
    EXPECT_EQ(std::vector<uint32_t>(v, v + 3), std::vector<uint32_t>(tri2.simplex(t), tri2.simplex(t) + 3));
    EXPECT_EQ(region, tri2.regions[t]);
  }

  Triangulation<4> four;
  EXPECT_THROW(write_triangulation(dir.path() / "x.ele", four, TriangulationFormat::NodeEle), InputError);
  write_triangulation(dir.path() / "x.simplices", four, TriangulationFormat::Simplices);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.ele"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.node"));
}

}  // namespace
}  // namespace sweepcdt::io
