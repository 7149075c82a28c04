// glTF specifics on hand-made files: node transforms (matrix, TRS, hierarchy, mirroring), primitive
// modes, every index checked (accessors, buffer views, nodes), required extensions, Draco-compressed
// primitives (encoded with Debian's draco_encoder when it is installed).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "surface_builders.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/io/write_surface.h"

namespace sweepcdt::io {
namespace {

using testing::expect_input_error;

std::string base64(const std::string& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = static_cast<uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 2]);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

// The unit tetrahedron (outward) as float32 positions + uint16 indices in one buffer.
std::string tetra_buffer() {
  std::string b;
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f}) b.append(reinterpret_cast<const char*>(&f), 4);
  for (uint16_t i : {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}) b.append(reinterpret_cast<const char*>(&i), 2);
  return b;
}

struct GltfParts {
  std::string nodes = R"([{"mesh": 0}])";
  std::string scene_nodes = "[0]";
  std::string primitive = R"({"attributes": {"POSITION": 0}, "indices": 1})";
  std::string accessors = R"([{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                              {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}])";
  std::string views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 24}])";
  std::string buffer = tetra_buffer();
  std::string extra;  // more top-level members
  std::string json() const {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": )" + scene_nodes + "}], \"nodes\": " + nodes +
           R"(, "meshes": [{"primitives": [)" + primitive + "]}], \"accessors\": " + accessors + ", \"bufferViews\": " + views +
           R"(, "buffers": [{"byteLength": )" + std::to_string(buffer.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
           base64(buffer) + "\"}]" + extra + "}";
  }
};

std::vector<double> points_of(const GltfParts& parts) { return read_soup_from_memory(parts.json(), "t.gltf").points; }

TEST(Gltf, PlainTetrahedron) {
  const Soup soup = read_soup_from_memory(GltfParts().json(), "t.gltf");
  EXPECT_EQ(soup.format, Format::Gltf);
  EXPECT_EQ(soup.num_triangles(), 4u);
  EXPECT_EQ(inspect(weld(soup)).reversed_triangles, 0u);
}

TEST(Gltf, NodeTransformsAreAppliedThroughTheHierarchy) {
  GltfParts parts;
  // Parent: translation (10, 0, 0); child: scale 2 then the mesh.
  parts.nodes = R"([{"children": [1], "translation": [10, 0, 0]}, {"mesh": 0, "scale": [2, 2, 2]}])";
  const auto p = points_of(parts);
  EXPECT_EQ(p, (std::vector<double>{10, 0, 0, 12, 0, 0, 10, 2, 0, 10, 0, 2}));
  // A column-major matrix with translation (1, 2, 3).
  parts.nodes = R"([{"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 1,2,3,1]}])";
  EXPECT_EQ(points_of(parts)[9 + 2], 4.0);
  // A rotation by 90 degrees about z: (x, y) -> (-y, x); the quaternion is (0, 0, sin 45, cos 45).
  parts.nodes = R"([{"mesh": 0, "rotation": [0, 0, 0.7071067811865476, 0.7071067811865476]}])";
  const auto r = points_of(parts);
  EXPECT_NEAR(r[3 * 1 + 1], 1.0, 1e-15);  // (1, 0, 0) -> (0, 1, 0): rounding makes rotations inexact
  EXPECT_NEAR(r[3 * 2 + 0], -1.0, 1e-15);
}

TEST(Gltf, AMirroringTransformReversesTheWindingSoTheSurfaceStaysOutward) {
  GltfParts parts;
  parts.nodes = R"([{"mesh": 0, "scale": [-1, 1, 1]}])";
  const Soup soup = read_soup_from_memory(parts.json(), "m.gltf");
  EXPECT_EQ(soup.points[3], -1.0);
  const SurfaceReport r = inspect(weld(soup));
  EXPECT_TRUE(r.valid());
  EXPECT_EQ(r.reversed_triangles, 0u);
}

TEST(Gltf, TheSameMeshInstancedTwiceGivesTwoShells) {
  GltfParts parts;
  parts.nodes = R"([{"mesh": 0}, {"mesh": 0, "translation": [5, 0, 0]}])";
  parts.scene_nodes = "[0, 1]";
  const SurfaceReport r = inspect(weld(read_soup_from_memory(parts.json(), "i.gltf")));
  EXPECT_EQ(r.shells.size(), 2u);
  EXPECT_EQ(r.triangles, 8u);
}

TEST(Gltf, StripsAndFans) {
  GltfParts parts;
  parts.primitive = R"({"attributes": {"POSITION": 0}, "mode": 5})";  // strip 0 1 2 3: (0,1,2), (2,1,3)
  EXPECT_EQ(read_soup_from_memory(parts.json(), "s.gltf").triangles, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));
  parts.primitive = R"({"attributes": {"POSITION": 0}, "mode": 6})";  // fan: (0,1,2), (0,2,3)
  EXPECT_EQ(read_soup_from_memory(parts.json(), "f.gltf").triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  parts.primitive = R"({"attributes": {"POSITION": 0}, "mode": 1})";  // lines bound nothing
  EXPECT_EQ(read_soup_from_memory(parts.json(), "l.gltf").num_triangles(), 0u);
}

TEST(Gltf, BadIndicesAndSizes) {
  GltfParts parts;
  parts.primitive = R"({"attributes": {"POSITION": 7}, "indices": 1})";
  expect_input_error("a.gltf", parts.json(), InputErrorKind::IndexOutOfRange, "accessor 7");
  parts = {};
  parts.views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 20}])";
  expect_input_error("v.gltf", parts.json(), InputErrorKind::SizeMismatch, "accessor 1");
  parts = {};
  parts.accessors = R"([{"bufferView": 0, "componentType": 5126, "count": 400000000, "type": "VEC3"},
                        {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}])";
  expect_input_error("c.gltf", parts.json(), InputErrorKind::SizeMismatch, "accessor 0");
  parts = {};
  std::string buffer = tetra_buffer();
  buffer[48] = 9;  // index 9 of 4 vertices
  parts.buffer = buffer;
  expect_input_error("i.gltf", parts.json(), InputErrorKind::IndexOutOfRange, "index 9");
  parts = {};
  parts.nodes = R"([{"mesh": 0, "children": [1]}, {"children": [0]}])";
  expect_input_error("n.gltf", parts.json(), InputErrorKind::Syntax, "node 0");
  parts = {};
  parts.extra = R"(, "extensionsRequired": ["KHR_mesh_quantization"], "extensionsUsed": ["KHR_mesh_quantization"])";
  expect_input_error("q.gltf", parts.json(), InputErrorKind::Unsupported, "KHR_mesh_quantization");
  expect_input_error("j.gltf", "{\"asset\": ", InputErrorKind::Syntax, "j.gltf: glTF");
  float nan = std::numeric_limits<float>::quiet_NaN();
  parts = {};
  parts.buffer.replace(4, 4, reinterpret_cast<const char*>(&nan), 4);
  expect_input_error("f.gltf", parts.json(), InputErrorKind::NonFinite, "accessor 0");
}

// Runs Debian's draco_encoder on an OBJ of `soup`; returns the .drc bytes, or "" if unavailable.
std::string draco_encode(const testing::TempDir& dir, const Soup& soup, const std::string& options) {
  const std::string encoder = SWEEPCDT_DRACO_ENCODER;
  if (encoder.empty() || encoder.ends_with("NOTFOUND")) return {};
  write_surface(dir.path() / "in.obj", soup, Format::Obj);
  const std::string cmd = encoder + " -i " + (dir.path() / "in.obj").string() + " -o " + (dir.path() / "out.drc").string() + " " + options + " > /dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0) return {};
  std::ifstream in(dir.path() / "out.drc", std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Gltf, DracoCompressedPrimitive) {
  testing::TempDir dir;
  const std::string drc = draco_encode(dir, testing::cube_soup(0, 1), "-qp 0");
  if (drc.empty()) GTEST_SKIP() << "draco_encoder (Debian package draco) is not installed";
  GltfParts parts;
  parts.buffer = drc;
  parts.views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": )" + std::to_string(drc.size()) + "}]";
  parts.accessors = R"([{"componentType": 5126, "count": 8, "type": "VEC3"}, {"componentType": 5123, "count": 36, "type": "SCALAR"}])";
  parts.primitive = R"({"attributes": {"POSITION": 0}, "indices": 1, "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}})";
  parts.extra = R"(, "extensionsRequired": ["KHR_draco_mesh_compression"], "extensionsUsed": ["KHR_draco_mesh_compression"])";
  const SurfaceReport r = inspect(weld(read_soup_from_memory(parts.json(), "d.gltf")));
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_EQ(r.points, 8u);
  EXPECT_TRUE(r.valid());
  EXPECT_EQ(r.reversed_triangles, 0u);

  parts.primitive = R"({"attributes": {"POSITION": 0}, "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 5}}}})";
  expect_input_error("d.gltf", parts.json(), InputErrorKind::IndexOutOfRange, "Draco POSITION");
  parts.primitive = R"({"attributes": {"POSITION": 0}, "extensions": {"KHR_draco_mesh_compression": {"bufferView": 3, "attributes": {"POSITION": 0}}}})";
  expect_input_error("d.gltf", parts.json(), InputErrorKind::IndexOutOfRange, "bufferView 3");
}

TEST(Draco, PointCloudIsRefused) {
  testing::TempDir dir;
  const std::string drc = draco_encode(dir, testing::cube_soup(0, 1), "-point_cloud");
  if (drc.empty()) GTEST_SKIP() << "draco_encoder (Debian package draco) is not installed";
  expect_input_error("p.drc", drc, InputErrorKind::Unsupported, "point cloud");
}

TEST(Draco, StreamWithMetadataReads) {
  // Named objects become Draco metadata, which precedes the connectivity counts checked before
  // decoding (draco_decode.cpp skips it).
  const std::string encoder = SWEEPCDT_DRACO_ENCODER;
  if (encoder.empty() || encoder.ends_with("NOTFOUND")) GTEST_SKIP() << "draco_encoder (Debian package draco) is not installed";
  testing::TempDir dir;
  const auto obj = dir.write("named.obj", "o first\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\no second\nf 1 4 3\nf 2 3 4\n");
  const auto drc = dir.path() / "named.drc";
  const std::string cmd = encoder + " -i " + obj.string() + " -o " + drc.string() + " --metadata -qp 0 > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const SurfaceReport r = inspect(weld(read_soup(drc)));
  EXPECT_EQ(r.triangles, 4u);
  EXPECT_TRUE(r.valid());
}

}  // namespace
}  // namespace sweepcdt::io
