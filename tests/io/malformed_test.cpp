// Hand-made malformed files, one or more per reader: each is rejected with the right kind of
// InputError and a message that names the file and the line, byte offset or element.
#include <cmath>
#include <cstring>
#include <limits>

#include "io_test_util.h"

namespace sweepcdt::io {
namespace {

using testing::expect_input_error;

const std::string kTetraOff = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

TEST(MalformedOff, TheValidTetrahedronReads) {
  const Soup soup = read_soup_from_memory(kTetraOff, "t.off");
  EXPECT_EQ(soup.num_points(), 4u);
  EXPECT_EQ(soup.num_triangles(), 4u);
}

TEST(MalformedOff, Truncated) {
  expect_input_error("t.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n", InputErrorKind::Truncated, "2 of 4 vertices");
  expect_input_error("t.off", kTetraOff.substr(0, kTetraOff.size() - 8), InputErrorKind::Truncated, "3 of 4 faces");
}

TEST(MalformedOff, NanAndInfinity) {
  expect_input_error("t.off", "OFF\n4 4 0\n0 0 0\n1 nan 0\n0 1 0\n0 0 1\n", InputErrorKind::NonFinite, "t.off:4:");
  expect_input_error("t.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 inf 0\n0 0 1\n", InputErrorKind::NonFinite, "t.off:5:");
  expect_input_error("t.off", "OFF\n4 4 0\n0 0 0\n1 0 1e999\n0 1 0\n0 0 1\n", InputErrorKind::NonFinite, "t.off:4:");
}

TEST(MalformedOff, HugeCountsAreRefusedBeforeAllocating) {
  expect_input_error("t.off", "OFF\n100000000000 1 0\n0 0 0\n", InputErrorKind::AbsurdCount, "t.off:2:");
  expect_input_error("t.off", "OFF\n3 99999999999 0\n0 0 0\n1 0 0\n0 1 0\n", InputErrorKind::AbsurdCount, "99999999999 faces");
}

TEST(MalformedOff, IndexOutOfRange) {
  expect_input_error("t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", InputErrorKind::IndexOutOfRange, "t.off:6: face 0 names vertex 3");
  expect_input_error("t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", InputErrorKind::IndexOutOfRange, "t.off:6:");
}

TEST(MalformedOff, SyntaxAndVariants) {
  expect_input_error("t.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n", InputErrorKind::Syntax, "t.off:4:");
  expect_input_error("t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", InputErrorKind::Syntax, "announces 4 vertices");
  expect_input_error("t.off", "4OFF\n1 0 0\n0 0 0 0\n", InputErrorKind::Unsupported, "t.off:1:");
  expect_input_error("t.off", "OFF BINARY\n", InputErrorKind::Unsupported, "binary OFF");
  expect_input_error("t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", InputErrorKind::BadPolygon, "t.off:6:");
}

TEST(MalformedOff, CommentsColoursAndHeaderCountsOnOneLineAreRead) {
  const Soup soup = read_soup_from_memory("COFF 3 1 0 # counts\n# a comment\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 1 1 1\n", "c.off");
  EXPECT_EQ(soup.num_points(), 3u);
  ASSERT_EQ(soup.num_triangles(), 1u);
  EXPECT_EQ(soup.points[3], 1.0);
}

std::string binary_stl(uint32_t announced, uint32_t stored, const char* header = "binary") {
  std::string bytes(80, '\0');
  std::memcpy(bytes.data(), header, std::strlen(header));
  bytes.append(reinterpret_cast<const char*>(&announced), 4);
  for (uint32_t t = 0; t < stored; ++t) {
    const float v[12] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, static_cast<float>(t)};
    bytes.append(reinterpret_cast<const char*>(v), sizeof v);
    bytes.append(2, '\0');
  }
  return bytes;
}

TEST(MalformedStl, BinaryIsDetectedBySizeEvenWhenTheHeaderSaysSolid) {
  const Soup soup = read_soup_from_memory(binary_stl(3, 3, "solid but binary"), "b.stl", ".stl");
  EXPECT_EQ(soup.format, Format::StlBinary);
  EXPECT_EQ(soup.num_triangles(), 3u);
}

TEST(MalformedStl, BinaryCountThatDisagreesWithTheSize) {
  expect_input_error("b.stl", binary_stl(5, 3), InputErrorKind::SizeMismatch, "byte 80");
  expect_input_error("b.stl", binary_stl(5, 3, "solid x"), InputErrorKind::SizeMismatch, "announces 5 triangles");
  expect_input_error("b.stl", binary_stl(4000000000u, 1), InputErrorKind::SizeMismatch, "byte 80");
}

TEST(MalformedStl, BinaryNan) {
  std::string bytes = binary_stl(2, 2);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bytes.data() + 84 + 50 + 12 + 4, &nan, 4);  // triangle 1, corner 0, y
  expect_input_error("b.stl", bytes, InputErrorKind::NonFinite, "triangle 1");
}

const std::string kAsciiFacet = "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";

TEST(MalformedStl, AsciiReadsSeveralSolids) {
  const Soup soup = read_soup_from_memory("solid a\n" + kAsciiFacet + "endsolid a\nsolid b\n" + kAsciiFacet + "endsolid b\n", "a.stl");
  EXPECT_EQ(soup.format, Format::StlAscii);
  EXPECT_EQ(soup.num_triangles(), 2u);
}

TEST(MalformedStl, AsciiTruncatedNanAndSyntax) {
  expect_input_error("a.stl", "solid a\n" + kAsciiFacet.substr(0, 60), InputErrorKind::Truncated, "a.stl:");
  expect_input_error("a.stl", "solid a\n" + kAsciiFacet, InputErrorKind::Truncated, "before 'endsolid'");
  std::string nan = "solid a\n" + kAsciiFacet + "endsolid\n";
  nan.replace(nan.find("vertex 1 0 0"), 12, "vertex 1 NaN 0");
  expect_input_error("a.stl", nan, InputErrorKind::NonFinite, "a.stl:5:");
  std::string quad = "solid a\n" + kAsciiFacet + "endsolid\n";
  quad.replace(quad.find(" endloop"), 8, "  vertex 1 1 0\n endloop");
  expect_input_error("a.stl", quad, InputErrorKind::Unsupported, "a.stl:7:");
  expect_input_error("a.stl", "solid a\nfacet normal 0 0 1\n outer lop\n", InputErrorKind::Syntax, "a.stl:3:");
}

TEST(MalformedObj, IndicesOutOfRange) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_input_error("m.obj", v + "f 1 2 4\n", InputErrorKind::IndexOutOfRange, "m.obj:4: face 0 names vertex 4");
  expect_input_error("m.obj", v + "f 0 1 2\n", InputErrorKind::IndexOutOfRange, "m.obj:4:");
  expect_input_error("m.obj", v + "f -4 -1 -2\n", InputErrorKind::IndexOutOfRange, "m.obj:4:");
  expect_input_error("m.obj", "f 1 2 3\n" + v, InputErrorKind::IndexOutOfRange, "m.obj:1:");
}

TEST(MalformedObj, NanSyntaxAndFreeForm) {
  expect_input_error("m.obj", "v 0 0 0\nv nan 0 0\n", InputErrorKind::NonFinite, "m.obj:2:");
  expect_input_error("m.obj", "v 0 0\n", InputErrorKind::Syntax, "m.obj:1:");
  expect_input_error("m.obj", "v 0 0 0\nfoo bar\n", InputErrorKind::Syntax, "m.obj:2:");
  expect_input_error("m.obj", "v 0 0 0\ncstype bspline\n", InputErrorKind::Unsupported, "m.obj:2:");
}

TEST(MalformedObj, RelativeIndicesSlashesAndCommentsAreRead) {
  const Soup soup = read_soup_from_memory("# made by hand\nv 0 0 0\nv 1 0 0\nvt 0 0\nv 0 1 0 # third\nvn 0 0 1\nf -3/1/1 -2//1 -1/1\n", "m.obj", ".obj");
  EXPECT_EQ(soup.format, Format::Obj);
  ASSERT_EQ(soup.num_triangles(), 1u);
  EXPECT_EQ(soup.triangles, (std::vector<uint32_t>{0, 1, 2}));
}

std::string ply_header(const std::string& format, uint64_t vertices, uint64_t faces) {
  return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(MalformedPly, AsciiErrors) {
  const std::string v = "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(read_soup_from_memory(ply_header("ascii", 3, 1) + v + "3 0 1 2\n", "p.ply").num_triangles(), 1u);
  expect_input_error("p.ply", ply_header("ascii", 3, 1) + v + "3 0 1 3\n", InputErrorKind::IndexOutOfRange, "face 0");
  expect_input_error("p.ply", ply_header("ascii", 3, 1) + v, InputErrorKind::Truncated, "p.ply:");
  expect_input_error("p.ply", ply_header("ascii", 3, 1) + "0 0 0\n1 nan 0\n", InputErrorKind::NonFinite, "p.ply:11:");
  expect_input_error("p.ply", ply_header("ascii", 100000000000, 1) + v, InputErrorKind::AbsurdCount, "100000000000 'vertex' elements");
  expect_input_error("p.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", InputErrorKind::Unsupported, "p.ply:2:");
}

TEST(MalformedPly, BinaryErrors) {
  std::string data;
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) data.append(reinterpret_cast<const char*>(&f), 4);
  std::string face = std::string(1, '\3');
  for (int32_t i : {0, 1, 2}) face.append(reinterpret_cast<const char*>(&i), 4);
  const std::string header = ply_header("binary_little_endian", 3, 1);
  EXPECT_EQ(read_soup_from_memory(header + data + face, "p.ply").num_triangles(), 1u);
  expect_input_error("p.ply", header + data + face.substr(0, 7), InputErrorKind::Truncated, "byte " + std::to_string(header.size() + data.size() + 5));
  expect_input_error("p.ply", ply_header("binary_little_endian", 3, 4000000000u) + data + face, InputErrorKind::AbsurdCount, "4000000000 'face' elements");
  std::string huge_list = face;
  huge_list[0] = '\xff';
  expect_input_error("p.ply", header + data + huge_list, InputErrorKind::AbsurdCount, "255 list entries");
}

TEST(ContentDetection, TheExtensionDoesNotDecide) {
  EXPECT_EQ(read_soup_from_memory(kTetraOff, "really_off.stl", ".stl").format, Format::Off);
  EXPECT_EQ(read_soup_from_memory(binary_stl(1, 1), "really_stl.obj", ".obj").format, Format::StlBinary);
  expect_input_error("x.dat", "hello world\n", InputErrorKind::UnknownFormat, "x.dat: not a supported");
  expect_input_error("x.stl", std::string(100, 'x'), InputErrorKind::SizeMismatch, "neither ascii STL");
  expect_input_error("x.off", "", InputErrorKind::Truncated, "empty");
}

TEST(MalformedDraco, GarbageAndFiles) {
  expect_input_error("d.drc", "DRACO" + std::string(40, '\x7f'), InputErrorKind::Syntax, "d.drc: ");
  testing::TempDir dir;
  try {
    read_soup(dir.path() / "missing.off");
    ADD_FAILURE() << "a missing file was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), InputErrorKind::Unreadable);
  }
}

}  // namespace
}  // namespace sweepcdt::io
