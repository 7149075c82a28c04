// Surfaces that arrive as arrays (the Python module, host applications' own meshes) instead of
// files, through the same steps and checks as a file: import_plc() is read_soup() + plc_of_soup().
//
//   (points, triangles) ──soup_of_arrays()──► Soup ──plc_of_soup()──► Plc<3>
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sweepcdt/io/snap.h"
#include "sweepcdt/io/soup.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::io {

// A soup from flat arrays (n x 3 coordinates, m x 3 point ids). Arrays cannot be malformed the way
// files can, but they can hold what no reader would produce, so this checks what the readers check:
// sizes that are multiples of 3, finite coordinates, ids in [0, n). Throws InputError naming `name`
// and the element ("point 7", "triangle 12").
Soup soup_of_arrays(std::span<const double> points, std::span<const int64_t> triangles, const std::string& name);

// weld → [snap_coordinates when snap_tolerance > 0] → inspect → to_plc, as import_plc() does after
// reading. `point_ids` (if given) receives, per soup point, its id in the PLC (welding merges
// equal points and drops unused ones), or kNone for a point no triangle uses. `for_cdt`: the PLC is
// to be meshed, so its check also tetrahedralizes the points on a second thread for cdt()
// (inspect(..., before_cdt)); the PLC's record holds that tetrahedralization (a few hundred bytes a
// point) until cdt() takes it or the last copy of the PLC goes. False for a PLC only read (to verify
// a mesh against it), or kept long before it is meshed.
Plc<3> plc_of_soup(const Soup& soup, double snap_tolerance = 0, SnapReport* snapped = nullptr,
                   std::vector<uint32_t>* point_ids = nullptr, bool for_cdt = true);

}  // namespace sweepcdt::io
