// read_node_list() and poly_dimension(): the node part that Triangle's and TetGen's files share.
#include "poly_files.h"

#include "file_io.h"

namespace sweepcdt::io::detail {

namespace {

// The node list at the scanner's position, which has `count` > 0 points.
NodeList read_nodes(TextScanner& in, int dimension, int64_t count) {
  const int64_t dim = in.to_integer(in.next_token(), "dimension");
  if (dim != dimension) in.fail(InputErrorKind::Unsupported, "dimension " + std::to_string(dim) + " (this reader reads " + std::to_string(dimension) + ")");
  const int64_t attributes = in.to_integer(in.next_token(), "number of attributes", 0, 1 << 20);
  const int64_t markers = in.to_integer(in.next_token(), "number of boundary markers", 0, 1);
  if (static_cast<uint64_t>(count) > in.bytes_left() / (2 * (dimension + 1)))
    in.fail(InputErrorKind::AbsurdCount, std::to_string(count) + " points announced, but only " + std::to_string(in.bytes_left()) + " bytes follow");
  if (count >= int64_t{kNone}) in.fail(InputErrorKind::AbsurdCount, "more than 2^32 - 2 points");
  NodeList list;
  list.points.reserve(static_cast<std::size_t>(count) * dimension);
  for (int64_t i = 0; i < count; ++i) {
    const int64_t id = in.to_integer(in.next_token(), "a point id");
    if (i == 0) {
      if (id != 0 && id != 1) in.fail(InputErrorKind::Syntax, "the first point id must be 0 or 1, not " + std::to_string(id));
      list.base = id;
    } else if (id != list.base + i) {
      in.fail(InputErrorKind::Syntax, "point ids must be consecutive: expected " + std::to_string(list.base + i) + ", found " + std::to_string(id));
    }
    for (int k = 0; k < dimension; ++k) list.points.push_back(in.to_double(in.next_token(), "a coordinate"));
    for (int64_t a = 0; a < attributes + markers; ++a) in.to_double(in.next_token(), "an attribute or marker");
  }
  return list;
}

}  // namespace

NodeList read_node_list(TextScanner& in, int dimension, const std::filesystem::path& node_file) {
  const int64_t count = in.to_integer(in.next_token(), "number of points", 0, INT64_MAX);
  if (count > 0) return read_nodes(in, dimension, count);
  // The points are in the .node file; the rest of this line is read past. The .node file itself
  // must list them: 0 there would send the reader back to the same file, without end.
  in.skip_rest_of_line();
  const std::string bytes = read_file_bytes(node_file);
  const std::string name = node_file.string();
  TextScanner nodes(bytes, name, '#');
  const int64_t node_count = nodes.to_integer(nodes.next_token(), "number of points", 0, INT64_MAX);
  if (node_count == 0) nodes.fail(InputErrorKind::Truncated, "no points");
  return read_nodes(nodes, dimension, node_count);
}

int poly_dimension(const std::string& bytes, const std::filesystem::path& file) {
  const std::string name = file.string();
  TextScanner in(bytes, name, '#');
  const int64_t count = in.to_integer(in.next_token(), "number of points", 0, INT64_MAX);
  if (count > 0) return static_cast<int>(in.to_integer(in.next_token(), "dimension", 2, 3));
  std::filesystem::path node = file;
  node.replace_extension(".node");
  const std::string node_bytes = read_file_bytes(node);
  const std::string node_name = node.string();
  TextScanner nodes(node_bytes, node_name, '#');
  nodes.to_integer(nodes.next_token(), "number of points", 0, INT64_MAX);
  return static_cast<int>(nodes.to_integer(nodes.next_token(), "dimension", 2, 3));
}

}  // namespace sweepcdt::io::detail
