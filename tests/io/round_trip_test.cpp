// Round trips: our writers (OFF, OBJ, binary PLY, STL ascii and binary) and Debian's draco_encoder,
// read back with our readers, give exactly the surface that was written.
#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "io_test_util.h"
#include "surface_builders.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/io/write_surface.h"

namespace sweepcdt::io {
namespace {

// A triangle as its three corner coordinates, rotated so the smallest corner comes first (keeps the
// orientation): equal sets of these mean the same oriented surface whatever the numbering.
using Corners = std::array<std::array<double, 3>, 3>;
std::vector<Corners> canonical_triangles(const Surface& s) {
  std::vector<Corners> out;
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    Corners c;
    for (int k = 0; k < 3; ++k) {
      const double* p = s.points.data() + 3 * std::size_t{s.triangles[3 * t + k]};
      c[k] = {p[0], p[1], p[2]};
    }
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Soup> samples() {
  std::vector<Soup> soups{testing::cube_soup(-1.5, 0.25)};
  for (const char* path : {"off/icosahedron.off", "stl_binary/spot.stl"}) {
    const auto file = std::filesystem::path(SWEEPCDT_SHARED_DATA) / path;
    if (std::filesystem::exists(file)) soups.push_back(read_soup(file));
  }
  return soups;
}

TEST(RoundTrip, OurWritersAndReadersAreExact) {
  testing::TempDir dir;
  for (const Soup& original : samples()) {
    const Surface welded = weld(original);
    for (Format format : {Format::Off, Format::Obj, Format::Ply, Format::StlAscii, Format::StlBinary}) {
      SCOPED_TRACE(original.file + " as " + to_string(format));
      const auto file = dir.path() / "surface.out";
      write_surface(file, original, format);
      const Soup back = read_soup(file);
      EXPECT_EQ(back.format, format);
      const bool indexed = format == Format::Off || format == Format::Obj || format == Format::Ply;
      if (indexed) {
        EXPECT_EQ(back.points, original.points);
        EXPECT_EQ(back.triangles, original.triangles);
      }
      // Binary STL stores float32: exact for these samples (float-valued or small binary fractions)
      // except the decimal coordinates of the icosahedron.
      if (format == Format::StlBinary && original.format == Format::Off) continue;
      const Surface back_welded = weld(back);
      EXPECT_EQ(back_welded.points, welded.points);
      EXPECT_EQ(back_welded.triangles, welded.triangles);
    }
  }
}

TEST(RoundTrip, DracoEncoderAndOurDracoReader) {
  const std::string encoder = SWEEPCDT_DRACO_ENCODER;
  if (encoder.empty() || encoder.ends_with("NOTFOUND")) GTEST_SKIP() << "draco_encoder (Debian package draco) is not installed";
  testing::TempDir dir;
  for (const Soup& original : samples()) {
    if (original.format == Format::Off) continue;  // decimal coordinates do not survive Draco's float32
    SCOPED_TRACE(original.file);
    const Surface welded = weld(original);
    write_surface(dir.path() / "in.obj", original, Format::Obj);
    // -qp 0: no quantisation, positions stay float32; -cl 10: the strongest (edgebreaker) compression.
    const std::string cmd = encoder + " -i " + (dir.path() / "in.obj").string() + " -o " + (dir.path() / "out.drc").string() + " -qp 0 -cl 10 > /dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const Soup back = read_soup(dir.path() / "out.drc");
    EXPECT_EQ(back.format, Format::Draco);
    const Surface back_welded = weld(back);
    EXPECT_EQ(back_welded.num_points(), welded.num_points());
    EXPECT_EQ(canonical_triangles(back_welded), canonical_triangles(welded)) << "Draco renumbers, but the oriented triangles are the same";
  }
}

TEST(RoundTrip, WritingToAnUnwritablePlaceIsAnError) {
  EXPECT_THROW(write_surface("/nonexistent-dir/x.off", testing::cube_soup(), Format::Off), InputError);
  EXPECT_THROW(write_surface("x.glb", testing::cube_soup(), Format::Glb), InputError);
}

}  // namespace
}  // namespace sweepcdt::io
