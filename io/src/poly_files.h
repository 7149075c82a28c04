// Shared pieces of the Triangle / TetGen PLC readers (read_triangle_poly.cpp, read_tetgen_poly.cpp).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "reader_util.h"
#include "sweepcdt/io/plc_file.h"

namespace sweepcdt::io::detail {

// A node list "<count> <dimension> <attributes> <markers>" then "<id> <coords> [attrs] [marker]".
// `count` == 0 in a .poly/.smesh means "in the .node file beside it": then `node_file` is read.
// The points, and the first id (0 or 1), which every later id is relative to.
struct NodeList {
  std::vector<double> points;
  int64_t base = 0;
};
NodeList read_node_list(TextScanner& in, int dimension, const std::filesystem::path& node_file);

// The dimension a .poly file announces (2: Triangle, 3: TetGen), from its first line or its .node.
int poly_dimension(const std::string& bytes, const std::filesystem::path& file);

Plc<2> read_triangle_poly(const std::string& bytes, const std::filesystem::path& file);
Plc<3> read_tetgen_poly(const std::string& bytes, const std::filesystem::path& file, bool smesh);
AnyPlc read_plc_text(const std::string& bytes, const std::string& file);

}  // namespace sweepcdt::io::detail
