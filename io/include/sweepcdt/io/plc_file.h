// PLC files in any dimension, for `sweepcdt cdt`, and triangulations of any dimension written as text.
//
//   read:  Triangle .poly (2D), TetGen .poly / .smesh (3D), sweepcdt .plc (any D = 2..5; the format is
//          documented in io/README.md)
//   write: Triangle .node/.ele (2D), TetGen .node/.ele (3D), sweepcdt .simplices text (any D)
#pragma once
#include <filesystem>
#include <variant>

#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::io {

using AnyPlc = std::variant<Plc<2>, Plc<3>, Plc<4>, Plc<5>>;

// Throws InputError naming file and line.
AnyPlc read_plc_file(const std::filesystem::path& file);

enum class TriangulationFormat : uint8_t {
  NodeEle,    // Triangle (D = 2) or TetGen (D = 3) .node/.ele
  Simplices,  // sweepcdt's text format for any D
};

// Atomic like write_volume_mesh (temporary file + rename). Throws InputError (Unreadable).
template <int D>
void write_triangulation(const std::filesystem::path& file, const Triangulation<D>& tri, TriangulationFormat format);

}  // namespace sweepcdt::io
