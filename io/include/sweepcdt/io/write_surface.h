// Writers for triangle surfaces, so that conversions and round trips need no other tool. Coordinates
// are written in the shortest form that reads back to the same double (std::to_chars), so a text
// round trip is exact; binary STL stores float32 and is exact only for float32-representable inputs.
#pragma once
#include <filesystem>

#include "sweepcdt/io/soup.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::io {

// `format` must be one of Off, StlAscii, StlBinary, Obj, Ply (binary little-endian, double
// coordinates). Throws InputError (Unreadable) if the file cannot be written, Unsupported for others.
void write_surface(const std::filesystem::path& file, const Soup& soup, Format format);

// The triangles of a PLC (its points and simplices; notations and tags are not written), e.g. to
// hand the same surface to another mesher.
void write_surface(const std::filesystem::path& file, const Plc<3>& plc, Format format);

}  // namespace sweepcdt::io
