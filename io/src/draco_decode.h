// Draco meshes (.drc files and glTF's KHR_draco_mesh_compression) into a Soup.
#pragma once
#include <memory>
#include <string_view>

#include "reader_util.h"

namespace draco {
class Mesh;
class PointAttribute;
}  // namespace draco

namespace sweepcdt::io::detail {

// Decodes a Draco mesh; Unsupported for a point cloud, Syntax for data Draco cannot decode.
std::unique_ptr<draco::Mesh> decode_draco_mesh(std::string_view bytes, const std::string& file, const Location& where);

// Appends every point of the mesh (its `position` attribute, 3 components) and every face.
void append_draco_mesh(const draco::Mesh& mesh, const draco::PointAttribute& position, Soup& soup, const Location& where);

}  // namespace sweepcdt::io::detail
