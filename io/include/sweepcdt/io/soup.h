// Soup: what every reader produces — triangles over points, exactly as stored in the file (no welding).
//
//   points:    n x 3 doubles (float32 inputs are widened exactly; glTF node transforms are applied in
//              double and round, see read.h)
//   triangles: m x 3 point ids, in the file's order and orientation; polygons are triangulated
//              in order, so triangle j of the soup is "input triangle j" everywhere downstream.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace sweepcdt::io {

enum class Format : uint8_t { Off, StlAscii, StlBinary, Obj, Ply, Gltf, Glb, Draco };

const char* to_string(Format format);  // "OFF", "STL ascii", "STL binary", "OBJ", "PLY", "glTF", "GLB", "Draco"

struct Soup {
  std::string file;  // as given by the caller; used in every message
  Format format = Format::Off;
  std::vector<double> points;
  std::vector<uint32_t> triangles;

  std::size_t num_points() const { return points.size() / 3; }
  std::size_t num_triangles() const { return triangles.size() / 3; }
};

}  // namespace sweepcdt::io
