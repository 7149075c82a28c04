// glTF 2.0 (.gltf with external or embedded buffers, and binary .glb): every triangle primitive of
// every node of the default scene, with the node's world matrix applied in double (see read.h for
// what that does to exactness), KHR_draco_mesh_compression decoded with libdraco. tinygltf parses the
// JSON; every index it hands back is checked here before use.
#include <draco/mesh/mesh.h>
#include <tiny_gltf.h>

#include <array>
#include <filesystem>

#include "draco_decode.h"
#include "gltf_draco_indices.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io::detail {
namespace {

using Matrix = std::array<double, 16>;  // column-major, as glTF stores it
constexpr Matrix kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Instancing lets a small file describe a huge soup; refuse soups beyond this many points per input
// byte (plain glTF needs 12 bytes per point, Draco rarely less than a tenth of a byte).
constexpr uint64_t kMaxPointsPerByte = 16;

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) c[4 * col + row] += a[4 * k + row] * b[4 * col + k];
  return c;
}

// T * R * S from a node's translation, rotation (unit quaternion x, y, z, w) and scale.
Matrix local_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    Matrix m;
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  Matrix m = kIdentity;
  if (node.rotation.size() == 4) {
    const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
    m = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0,
         2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0,
         2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0,
         0, 0, 0, 1};
  }
  if (node.scale.size() == 3)
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) m[4 * col + row] *= node.scale[col];
  if (node.translation.size() == 3)
    for (int row = 0; row < 3; ++row) m[12 + row] = node.translation[row];
  return m;
}

class GltfReader {
 public:
  GltfReader(const tinygltf::Model& model, Soup& soup, uint64_t input_bytes)
      : model_(model), soup_(soup), max_points_(kMaxPointsPerByte * input_bytes + 1024) {}

  void read_scene() {
    int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (model_.scenes.empty()) fail(InputErrorKind::Unsupported, soup_.file, Location::none(), "a glTF without scenes (nothing is shown)");
    if (scene >= static_cast<int>(model_.scenes.size())) bad("scene", scene, "does not exist");
    visited_.assign(model_.nodes.size(), 0);
    for (int root : model_.scenes[scene].nodes) visit(root, kIdentity);
  }

 private:
  [[noreturn]] void bad(const char* element, int64_t index, const std::string& why, InputErrorKind kind = InputErrorKind::IndexOutOfRange) const {
    fail(kind, soup_.file, Location::of(element, static_cast<uint64_t>(std::max<int64_t>(index, 0))), why);
  }
  template <class T>
  const T& at(const std::vector<T>& list, int index, const char* element) const {
    if (index < 0 || index >= static_cast<int>(list.size())) bad(element, index, "does not exist (there are " + std::to_string(list.size()) + ")");
    return list[index];
  }

  // Depth-first over the node tree; glTF requires a strict tree, so a node seen twice is an error.
  void visit(int root, const Matrix& root_parent) {
    std::vector<std::pair<int, Matrix>> stack{{root, root_parent}};
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      const tinygltf::Node& node = at(model_.nodes, index, "node");
      if (visited_[index]++) bad("node", index, "is reached twice: the node hierarchy is not a tree", InputErrorKind::Syntax);
      const Matrix world = multiply(parent, local_matrix(node));
      if (node.mesh >= 0) add_mesh(node.mesh, world);
      for (int child : node.children) stack.emplace_back(child, world);
    }
  }

  void add_mesh(int mesh_index, const Matrix& world) {
    const tinygltf::Mesh& mesh = at(model_.meshes, mesh_index, "mesh");
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = mesh.primitives[p];
      if (primitive.mode < TINYGLTF_MODE_TRIANGLES) continue;  // points and lines bound nothing
      if (primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN) bad("mesh", mesh_index, "has a primitive of unknown mode " + std::to_string(primitive.mode), InputErrorKind::Syntax);
      const std::size_t first_point = soup_.num_points(), first_triangle = soup_.num_triangles();
      const auto draco = primitive.extensions.find("KHR_draco_mesh_compression");
      if (draco != primitive.extensions.end()) {
        add_draco_primitive(mesh_index, primitive, draco->second);
      } else {
        add_plain_primitive(mesh_index, primitive);
      }
      if (soup_.num_points() > max_points_)
        bad("mesh", mesh_index, "instances make more than " + std::to_string(max_points_) + " vertices from this file", InputErrorKind::AbsurdCount);
      transform(world, first_point, first_triangle);
    }
  }

  void transform(const Matrix& m, std::size_t first_point, std::size_t first_triangle) {
    if (m == kIdentity) return;
    for (std::size_t i = first_point; i < soup_.num_points(); ++i) {
      double* p = soup_.points.data() + 3 * i;
      const double x = p[0], y = p[1], z = p[2];
      for (int row = 0; row < 3; ++row) p[row] = m[row] * x + m[4 + row] * y + m[8 + row] * z + m[12 + row];
      add_point_check(p);
    }
    // A mirroring transform reverses the winding (glTF spec, "Transformations"): keep triangles
    // counterclockwise seen from outside. Its sign is decided exactly: det M = orient(c0, c1, c2, 0).
    const double origin[3] = {0, 0, 0};
    const double* c0 = m.data();
    const double* c1 = m.data() + 4;
    const double* c2 = m.data() + 8;
    const auto det = predicates::orient<3>({c0, c1, c2, origin});
    if (det == predicates::Sign::Zero) fail(InputErrorKind::Unsupported, soup_.file, Location::none(), "a node transform that flattens its mesh (determinant 0)");
    if (det == predicates::Sign::Negative)
      for (std::size_t t = first_triangle; t < soup_.num_triangles(); ++t) std::swap(soup_.triangles[3 * t + 1], soup_.triangles[3 * t + 2]);
  }

  void add_point_check(const double* p) const {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(InputErrorKind::NonFinite, soup_.file, Location::none(), "a node transform makes a coordinate infinite or NaN");
  }

  // The bytes of accessor `index`, checked against its buffer view and buffer: element i starts at
  // data + i * stride and has `element_bytes` bytes.
  struct View {
    const unsigned char* data;
    std::size_t stride;
    std::size_t count;
  };
  View accessor_view(int index, int type, std::initializer_list<int> component_types, const char* what) const {
    const tinygltf::Accessor& a = at(model_.accessors, index, "accessor");
    if (a.sparse.isSparse) bad("accessor", index, "is sparse (not supported)", InputErrorKind::Unsupported);
    if (a.type != type || std::find(component_types.begin(), component_types.end(), a.componentType) == component_types.end())
      bad("accessor", index, std::string("has a type this reader does not support for ") + what, InputErrorKind::Unsupported);
    const tinygltf::BufferView& view = at(model_.bufferViews, a.bufferView, "bufferView");
    const tinygltf::Buffer& buffer = at(model_.buffers, view.buffer, "buffer");
    const std::size_t element = static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(a.componentType) * tinygltf::GetNumComponentsInType(a.type));
    const std::size_t stride = view.byteStride ? view.byteStride : element;
    if (stride < element) bad("accessor", index, "has a byte stride smaller than its element", InputErrorKind::Syntax);
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
      bad("bufferView", a.bufferView, "reaches past the end of its buffer", InputErrorKind::SizeMismatch);
    if (a.count > 0 && (a.byteOffset > view.byteLength || (a.count - 1) > (view.byteLength - a.byteOffset) / stride ||
                        (a.count - 1) * stride + element > view.byteLength - a.byteOffset))
      bad("accessor", index, std::to_string(a.count) + " elements reach past the end of bufferView " + std::to_string(a.bufferView), InputErrorKind::SizeMismatch);
    return {buffer.data.data() + view.byteOffset + a.byteOffset, stride, a.count};
  }

  void add_plain_primitive(int mesh_index, const tinygltf::Primitive& primitive) {
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) bad("mesh", mesh_index, "has a primitive without POSITION", InputErrorKind::Syntax);
    const View points = accessor_view(position->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, "positions");
    if (points.count > max_points_) bad("accessor", position->second, "has more vertices than the file can hold", InputErrorKind::AbsurdCount);
    const auto first = static_cast<uint32_t>(soup_.num_points());
    for (std::size_t i = 0; i < points.count; ++i) {
      float xyz[3];
      std::memcpy(xyz, points.data + i * points.stride, sizeof xyz);
      add_point(soup_, xyz[0], xyz[1], xyz[2], Location::of("accessor", static_cast<uint64_t>(position->second)));
    }
    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
      const View view = accessor_view(primitive.indices, TINYGLTF_TYPE_SCALAR,
                                      {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}, "indices");
      const int size = tinygltf::GetComponentSizeInBytes(model_.accessors[primitive.indices].componentType);
      indices.resize(view.count);
      for (std::size_t i = 0; i < view.count; ++i) {
        const unsigned char* e = view.data + i * view.stride;
        uint32_t v = 0;
        if (size == 1) v = e[0];
        if (size == 2) { uint16_t s; std::memcpy(&s, e, 2); v = s; }
        if (size == 4) std::memcpy(&v, e, 4);
        if (v >= points.count) bad("accessor", primitive.indices, "index " + std::to_string(v) + " is out of range (" + std::to_string(points.count) + " vertices)");
        indices[i] = v;
      }
    } else {
      indices.resize(points.count);
      for (std::size_t i = 0; i < points.count; ++i) indices[i] = static_cast<uint32_t>(i);
    }
    add_triangles(mesh_index, primitive.mode, indices, first);
  }

  // Triangles from the index list per mode (glTF spec, "Primitive topology").
  void add_triangles(int mesh_index, int mode, const std::vector<uint32_t>& ix, uint32_t first) {
    auto& out = soup_.triangles;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (ix.size() % 3 != 0) bad("mesh", mesh_index, "has a TRIANGLES primitive with " + std::to_string(ix.size()) + " indices, not a multiple of 3", InputErrorKind::Syntax);
      for (uint32_t i : ix) out.push_back(first + i);
      return;
    }
    for (std::size_t i = 0; i + 2 < ix.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_FAN) out.insert(out.end(), {first + ix[0], first + ix[i + 1], first + ix[i + 2]});
      else if (i % 2 == 0) out.insert(out.end(), {first + ix[i], first + ix[i + 1], first + ix[i + 2]});
      else out.insert(out.end(), {first + ix[i + 1], first + ix[i], first + ix[i + 2]});
    }
  }

  void add_draco_primitive(int mesh_index, const tinygltf::Primitive& primitive, const tinygltf::Value& extension) {
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES) bad("mesh", mesh_index, "has a Draco primitive that is not TRIANGLES", InputErrorKind::Unsupported);
    const tinygltf::Value& view_index = extension.Get("bufferView");
    const tinygltf::Value& attributes = extension.Get("attributes");
    if (!view_index.IsInt() || !attributes.IsObject() || !attributes.Get("POSITION").IsInt())
      bad("mesh", mesh_index, "has a KHR_draco_mesh_compression without bufferView or POSITION", InputErrorKind::Syntax);
    const tinygltf::BufferView& view = at(model_.bufferViews, view_index.Get<int>(), "bufferView");
    const tinygltf::Buffer& buffer = at(model_.buffers, view.buffer, "buffer");
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
      bad("bufferView", view_index.Get<int>(), "reaches past the end of its buffer", InputErrorKind::SizeMismatch);
    const std::string_view bytes(reinterpret_cast<const char*>(buffer.data.data()) + view.byteOffset, view.byteLength);
    const Location where = Location::of("bufferView", static_cast<uint64_t>(view_index.Get<int>()));
    const auto draco_mesh = decode_draco_mesh(bytes, soup_.file, where);
    const draco::PointAttribute* position = draco_mesh->GetAttributeByUniqueId(static_cast<uint32_t>(attributes.Get("POSITION").Get<int>()));
    if (position == nullptr) bad("mesh", mesh_index, "names a Draco POSITION attribute the Draco data does not have");
    append_draco_mesh(*draco_mesh, *position, soup_, where);
  }

  const tinygltf::Model& model_;
  Soup& soup_;
  uint64_t max_points_;
  std::vector<uint8_t> visited_;
};

bool ignore_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }

// External buffers: regular files only (not devices or FIFOs that never end), of bounded size.
bool read_buffer_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user_data) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    *err = "not a regular file: " + path;
    return false;
  }
  if (std::filesystem::file_size(path, ec) > UINT32_MAX) {
    *err = "buffer file larger than 4 GiB: " + path;
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, path, user_data);
}

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

}  // namespace

void read_gltf(std::string_view original, Soup& soup, bool binary) {
  const std::optional<std::string> prepared = without_draco_indices(original, binary);
  const std::string_view bytes = prepared ? std::string_view(*prepared) : original;
  if (bytes.size() >= UINT32_MAX) fail(InputErrorKind::Unsupported, soup.file, Location::none(), "glTF files of 4 GiB or more");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(ignore_image, nullptr);
  loader.SetFsCallbacks({tinygltf::FileExists, tinygltf::ExpandFilePath, read_buffer_file, tinygltf::WriteWholeFile, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  const std::string base_dir = std::filesystem::path(soup.file).parent_path().string();
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), size, base_dir)
                         : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, base_dir);
  if (!ok) fail(InputErrorKind::Syntax, soup.file, Location::none(), "glTF: " + first_line(err.empty() ? std::string("cannot be parsed") : err));
  for (const std::string& required : model.extensionsRequired)
    if (required != "KHR_draco_mesh_compression")
      fail(InputErrorKind::Unsupported, soup.file, Location::none(), "glTF extension " + required + " (required by the file)");
  uint64_t input_bytes = bytes.size();
  for (const auto& b : model.buffers) input_bytes += b.data.size();
  GltfReader(model, soup, input_bytes).read_scene();
}

}  // namespace sweepcdt::io::detail
