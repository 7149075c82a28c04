// Prepares glTF with KHR_draco_mesh_compression for tinygltf 2.7.0, which (built without its Draco
// path, see tinygltf_impl.cpp) rejects a primitive whose "indices" accessor has no bufferView — the
// normal case for Draco, whose faces live in the compressed data. The Draco faces are what
// read_gltf.cpp uses, so the "indices" member of Draco primitives is dropped before parsing.
#include <nlohmann/json.hpp>

#include <cstring>

#include "gltf_draco_indices.h"

namespace sweepcdt::io::detail {
namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";

// Drops "indices" from Draco primitives; false if there was nothing to change.
bool drop_indices(nlohmann::json& gltf) {
  bool changed = false;
  auto meshes = gltf.find("meshes");
  if (meshes == gltf.end() || !meshes->is_array()) return false;
  for (auto& mesh : *meshes) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    for (auto& primitive : mesh["primitives"]) {
      if (!primitive.is_object() || !primitive.contains("extensions") || !primitive["extensions"].is_object()) continue;
      if (primitive["extensions"].contains(kDraco) && primitive.erase("indices") > 0) changed = true;
    }
  }
  return changed;
}

uint32_t read_u32(std::string_view b, std::size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

void put_u32(std::string& b, uint32_t v) { b.append(reinterpret_cast<const char*>(&v), 4); }

}  // namespace

std::optional<std::string> without_draco_indices(std::string_view bytes, bool binary) {
  if (bytes.find(kDraco) == std::string_view::npos) return std::nullopt;
  // GLB: 12-byte header, then the JSON chunk (length, type, data), then the rest (the BIN chunk).
  std::string_view json_text = bytes;
  if (binary) {
    if (bytes.size() < 20) return std::nullopt;
    const uint32_t json_length = read_u32(bytes, 12);
    if (json_length > bytes.size() - 20) return std::nullopt;  // malformed: tinygltf will say so
    json_text = bytes.substr(20, json_length);
  }
  nlohmann::json gltf = nlohmann::json::parse(json_text, nullptr, /*allow_exceptions=*/false);
  if (gltf.is_discarded() || !gltf.is_object() || !drop_indices(gltf)) return std::nullopt;
  std::string json = gltf.dump();
  if (!binary) return json;
  json.append((4 - json.size() % 4) % 4, ' ');  // chunks are 4-byte aligned, padded with spaces
  const std::string_view rest = bytes.substr(20 + read_u32(bytes, 12));
  std::string glb(bytes.substr(0, 8));
  put_u32(glb, static_cast<uint32_t>(12 + 8 + json.size() + rest.size()));
  put_u32(glb, static_cast<uint32_t>(json.size()));
  put_u32(glb, read_u32(bytes, 16));
  return glb + json + std::string(rest);
}

}  // namespace sweepcdt::io::detail
