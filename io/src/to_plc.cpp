#include "sweepcdt/io/to_plc.h"

#include "sweepcdt/io/read.h"
#include "sweepcdt/io/surface_arrays.h"

namespace sweepcdt::io {

Plc<3> to_plc(const Surface& surface, const SurfaceReport& report) {
  report.throw_if_invalid();
  Plc<3> plc;
  plc.points = surface.points;
  plc.simplices = surface.triangles;
  const std::size_t m = surface.num_triangles();
  plc.exterior.resize(m);
  plc.tags.resize(m);
  for (std::size_t t = 0; t < m; ++t) {
    // Counterclockwise from outside the material: the material is on the positive side.
    plc.exterior[t] = report.reverse[t] ? ExteriorSide::Positive : ExteriorSide::Negative;
    plc.tags[t] = static_cast<uint32_t>(t);
  }
  plc.checked = report.checked;  // ignored by core unless it covers these points and simplices
  return plc;
}

Plc<3> import_plc(const std::filesystem::path& file, double snap_tolerance, SnapReport* snapped, bool for_cdt) {
  return plc_of_soup(read_soup(file), snap_tolerance, snapped, nullptr, for_cdt);
}

}  // namespace sweepcdt::io
