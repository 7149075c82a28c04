// Draco .drc: a compressed triangle mesh (a point cloud is refused). Corners split at attribute seams
// arrive as separate points, which weld() merges.
#include <draco/mesh/mesh.h>

#include "draco_decode.h"

namespace sweepcdt::io::detail {

void read_draco(std::string_view bytes, Soup& soup) {
  const auto mesh = decode_draco_mesh(bytes, soup.file, Location::none());
  const draco::PointAttribute* position = mesh->GetNamedAttribute(draco::GeometryAttribute::POSITION);
  if (position == nullptr) fail(InputErrorKind::Unsupported, soup.file, Location::none(), "a Draco mesh without positions");
  append_draco_mesh(*mesh, *position, soup, Location::none());
}

}  // namespace sweepcdt::io::detail
