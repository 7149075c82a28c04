#include "draco_decode.h"

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <draco/mesh/mesh.h>

#include <cstring>

namespace sweepcdt::io::detail {
namespace {

// libdraco reserves memory by the face and vertex counts in the stream before it checks them against
// the data (a 299-byte file made it ask for 2.6 GB), so the counts are read here first and bounded
// by the stream size. Edgebreaker needs about 2 bits per face; this bound is far above any real file.
constexpr uint64_t kMaxElementsPerByte = 64;

// Reads Draco's bitstream (draco/compression: header, optional metadata, connectivity header) just
// far enough to find the face and vertex counts; false if they cannot be found.
class DracoHeader {
 public:
  explicit DracoHeader(std::string_view b) : b_(b) {}

  bool read(uint64_t& faces, uint64_t& vertices) {
    uint8_t major, minor, type, method;
    uint16_t flags;
    if (!skip(5) || !u8(major) || !u8(minor) || !u8(type) || !u8(method) || !u16(flags)) return false;
    const int version = major << 8 | minor;  // as DRACO_BITSTREAM_VERSION(major, minor)
    if (type != 1) return false;                                     // not a triangular mesh
    // Metadata (flag 0x8000) exists from bitstream 1.3 on; older decoders ignore the flag.
    if (version >= 0x0103 && (flags & 0x8000) && !(skip_attribute_metadata() && skip_metadata(0))) return false;
    if (method == 0) {                                               // sequential
      return version < 0x0202 ? u32(faces) && u32(vertices) : varint(faces) && varint(vertices);
    }
    uint8_t traversal;
    uint64_t new_vertices;
    if (method != 1 || !u8(traversal)) return false;                 // edgebreaker
    if (version < 0x0202 && !(version < 0x0200 ? u32(new_vertices) : varint(new_vertices))) return false;
    return version < 0x0200 ? u32(vertices) && u32(faces) : varint(vertices) && varint(faces);
  }

 private:
  bool skip(uint64_t n) {
    if (b_.size() - pos_ < n) return false;
    pos_ += n;
    return true;
  }
  bool u8(uint8_t& v) {
    if (pos_ >= b_.size()) return false;
    v = static_cast<uint8_t>(b_[pos_++]);
    return true;
  }
  bool u16(uint16_t& v) {
    if (b_.size() - pos_ < 2) return false;
    std::memcpy(&v, b_.data() + pos_, 2);
    pos_ += 2;
    return true;
  }
  bool u32(uint64_t& v) {
    uint32_t w;
    if (b_.size() - pos_ < 4) return false;
    std::memcpy(&w, b_.data() + pos_, 4);
    pos_ += 4;
    v = w;
    return true;
  }
  bool varint(uint64_t& v) {  // little-endian base 128, at most 5 bytes for 32 bits
    v = 0;
    for (int shift = 0; shift < 35; shift += 7) {
      uint8_t byte;
      if (!u8(byte)) return false;
      v |= uint64_t{byte & 0x7fu} << shift;
      if (!(byte & 0x80)) return true;
    }
    return false;
  }
  bool skip_name() {
    uint8_t size;
    return u8(size) && skip(size);
  }
  bool skip_metadata(int depth) {  // entries (name, value), then named sub-metadata
    uint64_t entries, children;
    if (depth > 32 || !varint(entries)) return false;
    for (uint64_t i = 0; i < entries; ++i)
      if (!skip_name() || !skip_name()) return false;
    if (!varint(children)) return false;
    for (uint64_t i = 0; i < children; ++i)
      if (!skip_name() || !skip_metadata(depth + 1)) return false;
    return true;
  }
  bool skip_attribute_metadata() {
    uint64_t count, id;
    if (!varint(count)) return false;
    for (uint64_t i = 0; i < count; ++i)
      if (!varint(id) || !skip_metadata(0)) return false;
    return true;
  }

  std::string_view b_;
  std::size_t pos_ = 0;
};

}  // namespace

std::unique_ptr<draco::Mesh> decode_draco_mesh(std::string_view bytes, const std::string& file, const Location& where) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok()) fail(InputErrorKind::Syntax, file, where, "not a Draco stream: " + type.status().error_msg_string());
  if (type.value() == draco::POINT_CLOUD) fail(InputErrorKind::Unsupported, file, where, "a Draco point cloud, not a triangle mesh");
  if (type.value() != draco::TRIANGULAR_MESH) fail(InputErrorKind::Unsupported, file, where, "an unknown Draco geometry type");
  uint64_t faces = 0, vertices = 0;
  if (!DracoHeader(bytes).read(faces, vertices))
    fail(InputErrorKind::Syntax, file, where, "the Draco stream ends or is malformed before its face and vertex counts");
  const uint64_t limit = kMaxElementsPerByte * bytes.size() + 1024;
  if (faces > limit || vertices > limit)
    fail(InputErrorKind::AbsurdCount, file, where,
         "the Draco stream announces " + std::to_string(faces) + " faces and " + std::to_string(vertices) +
             " vertices in " + std::to_string(bytes.size()) + " bytes");
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
