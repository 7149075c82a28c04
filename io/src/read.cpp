// read_soup(): the format from the content, then the reader for it.
#include "sweepcdt/io/read.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>

#include "reader_util.h"

namespace sweepcdt::io {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The first whitespace-separated word of the text, skipping '#' comment lines (OBJ, PLY-free text).
std::string_view first_word(std::string_view bytes, bool skip_comments) {
  std::size_t i = 0;
  while (i < bytes.size()) {
    while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
    if (skip_comments && i < bytes.size() && bytes[i] == '#') {
      while (i < bytes.size() && bytes[i] != '\n') ++i;
      continue;
    }
    break;
  }
  std::size_t end = i;
  while (end < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[end]))) ++end;
  return bytes.substr(i, end - i);
}

bool is_off_keyword(std::string_view w) { return w.size() >= 3 && w.size() <= 8 && w.substr(w.size() - 3) == "OFF"; }

}  // namespace

Format detect_format(std::string_view bytes, const std::string& name, const std::string& extension) {
  if (bytes.substr(0, 4) == "glTF") return Format::Glb;
  if (bytes.substr(0, 5) == "DRACO") return Format::Draco;
  // Binary STL by its size formula, before any text test: binary headers often start with "solid".
  uint32_t stl_count = 0;
  if (bytes.size() >= 84) std::memcpy(&stl_count, bytes.data() + 80, 4);
  const uint64_t stl_bytes = 84 + 50 * uint64_t{stl_count};
  if (bytes.size() >= 84 && bytes.size() == stl_bytes) return Format::StlBinary;
  const std::string_view word = first_word(bytes, false);
  if (word == "solid") {
    // A binary STL whose size does not fit its count also starts with "solid" now and then.
    if (bytes.size() >= 84 && std::memchr(bytes.data(), '\0', std::min<std::size_t>(bytes.size(), 1024)) != nullptr)
      detail::fail(InputErrorKind::SizeMismatch, name, Location::byte(80),
                   "binary STL header announces " + std::to_string(stl_count) + " triangles, which take " +
                       std::to_string(stl_bytes) + " bytes, but the file has " + std::to_string(bytes.size()));
    return Format::StlAscii;
  }
  if (word == "ply") return Format::Ply;
  if (is_off_keyword(word)) return Format::Off;
  if (!word.empty() && word[0] == '{') return Format::Gltf;
  const std::string ext = lower(extension);
  const std::string_view obj_word = first_word(bytes, true);
  for (std::string_view key : {"v", "vn", "vt", "f", "o", "g", "s", "mtllib", "usemtl"})
    if (obj_word == key) return Format::Obj;
  if (ext == ".obj" && obj_word.empty()) return Format::Obj;  // comments only: an empty OBJ
  if (ext == ".stl" && bytes.size() >= 84)
    detail::fail(InputErrorKind::SizeMismatch, name, Location::byte(80),
                 "neither ascii STL (no 'solid') nor binary STL: the header announces " + std::to_string(stl_count) +
                     " triangles, i.e. " + std::to_string(stl_bytes) + " bytes, but the file has " + std::to_string(bytes.size()));
  if (bytes.empty()) detail::fail(InputErrorKind::Truncated, name, Location::none(), "the file is empty");
  detail::fail(InputErrorKind::UnknownFormat, name, Location::none(),
               "not a supported surface format (OFF, STL, OBJ, PLY, glTF/GLB, Draco) by its content");
}

Soup read_soup_from_memory(std::string_view bytes, const std::string& name, const std::string& extension) {
  Soup soup;
  soup.file = name;
  soup.format = detect_format(bytes, name, extension);
  switch (soup.format) {
    case Format::Off: detail::read_off(bytes, soup); break;
    case Format::StlAscii: detail::read_stl_ascii(bytes, soup); break;
    case Format::StlBinary: detail::read_stl_binary(bytes, soup); break;
    case Format::Obj: detail::read_obj(bytes, soup); break;
    case Format::Ply: detail::read_ply(bytes, soup); break;
    case Format::Gltf: detail::read_gltf(bytes, soup, false); break;
    case Format::Glb: detail::read_gltf(bytes, soup, true); break;
    case Format::Draco: detail::read_draco(bytes, soup); break;
  }
  return soup;
}

Soup read_soup(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    detail::fail(InputErrorKind::Unreadable, name, Location::none(), ec ? ec.message() : "not a regular file");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) detail::fail(InputErrorKind::Unreadable, name, Location::none(), ec.message());
  if (size > kMaxFileBytes)
    detail::fail(InputErrorKind::Unsupported, name, Location::none(), "files larger than " + std::to_string(kMaxFileBytes) + " bytes");
  std::ifstream in(file, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size)))
    detail::fail(InputErrorKind::Unreadable, name, Location::none(), "cannot read the file");
  return read_soup_from_memory(bytes, name, file.extension().string());
}

}  // namespace sweepcdt::io
