#include "sweepcdt/io/surface_arrays.h"

#include <cmath>

#include "sweepcdt/io/error.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::io {

Soup soup_of_arrays(std::span<const double> points, std::span<const int64_t> triangles, const std::string& name) {
  if (points.size() % 3 != 0)
    throw InputError(InputErrorKind::SizeMismatch, name, Location::none(),
                     std::to_string(points.size()) + " coordinates are not n x 3 points");
  if (triangles.size() % 3 != 0)
    throw InputError(InputErrorKind::SizeMismatch, name, Location::none(),
                     std::to_string(triangles.size()) + " point ids are not m x 3 triangles");
  const std::size_t n = points.size() / 3;
  // Ids are 32-bit everywhere downstream.
  if (n >= kNone)
    throw InputError(InputErrorKind::AbsurdCount, name, Location::none(), std::to_string(n) + " points are too many");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i]))
      throw InputError(InputErrorKind::NonFinite, name, Location::of("point", i / 3),
                       "coordinate " + std::to_string(i % 3) + " is not finite");
  Soup soup;
  soup.file = name;
  soup.points.assign(points.begin(), points.end());
  soup.triangles.reserve(triangles.size());
  for (std::size_t c = 0; c < triangles.size(); ++c) {
    const int64_t id = triangles[c];
    if (id < 0 || static_cast<uint64_t>(id) >= n)
      throw InputError(InputErrorKind::IndexOutOfRange, name, Location::of("triangle", c / 3),
                       "point id " + std::to_string(id) + " is not in [0, " + std::to_string(n) + ")");
    soup.triangles.push_back(static_cast<uint32_t>(id));
  }
  return soup;
}

Plc<3> plc_of_soup(const Soup& soup, double snap_tolerance, SnapReport* snapped, std::vector<uint32_t>* point_ids, bool for_cdt) {
  Surface surface = weld(soup);
  if (snap_tolerance > 0) {
    SnapReport report;
    surface = snap_coordinates(surface, snap_tolerance, report);
    if (snapped) *snapped = report;
  }
  if (point_ids) {
    // Triangle j of the surface is soup triangle j (weld and snap keep the order), so corners pair up.
    point_ids->assign(soup.num_points(), kNone);
    for (std::size_t c = 0; c < soup.triangles.size(); ++c) (*point_ids)[soup.triangles[c]] = surface.triangles[c];
  }
  return to_plc(surface, inspect(surface, 10, for_cdt));
}

}  // namespace sweepcdt::io
