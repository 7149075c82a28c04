#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace sweepcdt::io::detail {

// The glTF (or GLB) with "indices" removed from every primitive that has KHR_draco_mesh_compression,
// or nothing if no primitive has it (or the JSON does not parse: tinygltf then reports the error).
std::optional<std::string> without_draco_indices(std::string_view bytes, bool binary);

}  // namespace sweepcdt::io::detail
