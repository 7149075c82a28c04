#include "draco_decode.h"

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <draco/mesh/mesh.h>

namespace sweepcdt::io::detail {

std::unique_ptr<draco::Mesh> decode_draco_mesh(std::string_view bytes, const std::string& file, const Location& where) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok()) fail(InputErrorKind::Syntax, file, where, "not a Draco stream: " + type.status().error_msg_string());
  if (type.value() == draco::POINT_CLOUD) fail(InputErrorKind::Unsupported, file, where, "a Draco point cloud, not a triangle mesh");
  if (type.value() != draco::TRIANGULAR_MESH) fail(InputErrorKind::Unsupported, file, where, "an unknown Draco geometry type");
  draco::Decoder decoder;
  auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
  if (!mesh.ok()) fail(InputErrorKind::Syntax, file, where, "Draco cannot decode the mesh: " + mesh.status().error_msg_string());
  return std::move(mesh).value();
}

void append_draco_mesh(const draco::Mesh& mesh, const draco::PointAttribute& position, Soup& soup, const Location& where) {
  if (position.num_components() != 3)
    fail(InputErrorKind::Unsupported, soup.file, where, "Draco positions with " + std::to_string(position.num_components()) + " components");
  const auto first = static_cast<uint64_t>(soup.num_points());
  const uint32_t n = mesh.num_points();
  if (!position.is_mapping_identity() && position.indices_map_size() < n)
    fail(InputErrorKind::IndexOutOfRange, soup.file, where, "Draco positions are mapped for fewer points than the mesh has");
  soup.points.reserve(soup.points.size() + 3 * std::size_t{n});
  for (draco::PointIndex i(0); i < n; ++i) {
    const draco::AttributeValueIndex value = position.mapped_index(i);
    double xyz[3];
    if (value.value() >= position.size() || !position.ConvertValue<double>(value, 3, xyz))
      fail(InputErrorKind::IndexOutOfRange, soup.file, where, "Draco point " + std::to_string(i.value()) + " has no position");
    add_point(soup, xyz[0], xyz[1], xyz[2], where);
  }
  soup.triangles.reserve(soup.triangles.size() + 3 * std::size_t{mesh.num_faces()});
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const uint32_t id = mesh.face(f)[c].value();
      if (id >= n) fail(InputErrorKind::IndexOutOfRange, soup.file, where, "Draco face " + std::to_string(f.value()) + " names point " + std::to_string(id));
      soup.triangles.push_back(static_cast<uint32_t>(first + id));
    }
  }
}

}  // namespace sweepcdt::io::detail
