// Reading a triangle surface from OFF, STL (ascii/binary), OBJ, PLY, glTF/GLB (with
// KHR_draco_mesh_compression) or Draco .drc into a Soup.
//
// The format is decided by the content (magic bytes, the binary STL size 84 + 50 n, the first
// keyword), so a wrong extension does not matter; the extension only decides between text formats
// whose first line says nothing (an OBJ that starts with a comment). Counts are checked against the
// file size before anything is reserved, so memory stays proportional to the file size.
//
// glTF: every triangle primitive (modes TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN) of every node of the
// default scene, with the node's world matrix applied in double arithmetic. A transform other than
// the identity makes coordinates inexact (rounded products), which can, in principle, create or
// remove a degeneracy that the untransformed model did not have; every later decision is exact on
// the transformed doubles.
//
// Throws InputError (sweepcdt/io/error.h) for anything malformed; never prints.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "sweepcdt/io/soup.h"

namespace sweepcdt::io {

// Largest file read_soup() accepts (the whole file is held in memory while reading).
inline constexpr uint64_t kMaxFileBytes = uint64_t{4} << 30;

Soup read_soup(const std::filesystem::path& file);

// Reads from memory. `name` is used in messages and to resolve glTF's external buffers (relative to
// its directory); `extension` (e.g. ".obj", may be empty) is only a hint, as for files.
Soup read_soup_from_memory(std::string_view bytes, const std::string& name, const std::string& extension = {});

// The format the content says (throws InputError UnknownFormat if none).
Format detect_format(std::string_view bytes, const std::string& name, const std::string& extension);

}  // namespace sweepcdt::io
