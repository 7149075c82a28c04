// write_surface(): OFF, STL (ascii/binary), OBJ and binary PLY, written to a temporary file that is
// renamed into place, so a failure never leaves a half-written file.
#include "sweepcdt/io/write_surface.h"

#include <charconv>
#include <cstring>

#include "file_io.h"
#include "reader_util.h"

namespace sweepcdt::io {
namespace {

// Shortest text that reads back as the same double.
std::string shortest(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, end);
}

std::string point_text(const Soup& s, std::size_t i) {
  return shortest(s.points[3 * i]) + " " + shortest(s.points[3 * i + 1]) + " " + shortest(s.points[3 * i + 2]);
}

template <class T>
void put(std::string& out, T v) {  // little-endian hosts only (checked below)
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}
static_assert(std::endian::native == std::endian::little, "the binary writers assume a little-endian host");

std::string off(const Soup& s) {
  std::string out = "OFF\n" + std::to_string(s.num_points()) + " " + std::to_string(s.num_triangles()) + " 0\n";
  for (std::size_t i = 0; i < s.num_points(); ++i) out += point_text(s, i) + "\n";
  for (std::size_t t = 0; t < s.num_triangles(); ++t)
    out += "3 " + std::to_string(s.triangles[3 * t]) + " " + std::to_string(s.triangles[3 * t + 1]) + " " + std::to_string(s.triangles[3 * t + 2]) + "\n";
  return out;
}

std::string obj(const Soup& s) {
  std::string out;
  for (std::size_t i = 0; i < s.num_points(); ++i) out += "v " + point_text(s, i) + "\n";
  for (std::size_t t = 0; t < s.num_triangles(); ++t)
    out += "f " + std::to_string(s.triangles[3 * t] + 1) + " " + std::to_string(s.triangles[3 * t + 1] + 1) + " " + std::to_string(s.triangles[3 * t + 2] + 1) + "\n";
  return out;
}

std::string ply(const Soup& s) {
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by sweepcdt\nelement vertex " + std::to_string(s.num_points()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(s.num_triangles()) +
                    "\nproperty list uchar uint vertex_indices\nend_header\n";
  for (double x : s.points) put(out, x);
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    put<uint8_t>(out, 3);
    for (int c = 0; c < 3; ++c) put<uint32_t>(out, s.triangles[3 * t + c]);
  }
  return out;
}

std::string stl_ascii(const Soup& s) {
  std::string out = "solid sweepcdt\n";
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    out += "facet normal 0 0 0\nouter loop\n";
    for (int c = 0; c < 3; ++c) out += "vertex " + point_text(s, s.triangles[3 * t + c]) + "\n";
    out += "endloop\nendfacet\n";
  }
  out += "endsolid sweepcdt\n";
  return out;
}

std::string stl_binary(const Soup& s) {
  std::string out(80, ' ');
  std::memcpy(out.data(), "binary STL written by sweepcdt", 30);  // not "solid": some readers sniff it
  put<uint32_t>(out, static_cast<uint32_t>(s.num_triangles()));
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    for (int k = 0; k < 3; ++k) put<float>(out, 0.0f);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) put<float>(out, static_cast<float>(s.points[3 * std::size_t{s.triangles[3 * t + c]} + k]));
    put<uint16_t>(out, 0);
  }
  return out;
}

}  // namespace

void write_surface(const std::filesystem::path& file, const Soup& soup, Format format) {
  std::string bytes;
  switch (format) {
    case Format::Off: bytes = off(soup); break;
    case Format::Obj: bytes = obj(soup); break;
    case Format::Ply: bytes = ply(soup); break;
    case Format::StlAscii: bytes = stl_ascii(soup); break;
    case Format::StlBinary: bytes = stl_binary(soup); break;
    default: detail::fail(InputErrorKind::Unsupported, file.string(), Location::none(), std::string("writing ") + to_string(format));
  }
  // A fresh temporary beside the target, removed on failure (file_io.h).
  detail::write_files_atomically({{file, std::move(bytes)}}, file.string());
}

void write_surface(const std::filesystem::path& file, const Plc<3>& plc, Format format) {
  Soup soup;
  soup.file = file.string();
  soup.points = plc.points;
  soup.triangles = plc.simplices;
  write_surface(file, soup, format);
}

}  // namespace sweepcdt::io
