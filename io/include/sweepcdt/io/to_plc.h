// A valid closed surface as a facet-bounded PLC (sweepcdt/plc.h).
//
// Each shell is oriented by its nesting depth: outer boundaries of bodies (depth 0, 2, ...) with the
// material inside, cavities (depth 1, 3, ...) with the material outside. Every triangle keeps its
// vertices in input order; its exterior notation says which side is outside the material
// (ExteriorSide::Negative for a triangle counterclockwise seen from outside the material, Positive
// for one the report marks as reversed). Cavities are thereby holes, and bodies inside cavities are
// separate connected parts of the domain, which cdt() numbers as separate regions.
//
//   plc.points  = surface.points (welded)
//   plc.tags[j] = j, the input triangle index (triangle j of the soup)
#pragma once
#include <filesystem>

#include "sweepcdt/io/snap.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::io {

// Throws SurfaceError if !report.valid().
Plc<3> to_plc(const Surface& surface, const SurfaceReport& report);

// read_soup → weld → inspect → to_plc in one call, for callers that want the PLC or an error.
// With snap_tolerance > 0 the welded surface is snapped first (snap.h), and `snapped` (if given)
// says what moved. `for_cdt`: as for plc_of_soup (surface_arrays.h).
Plc<3> import_plc(const std::filesystem::path& file, double snap_tolerance = 0, SnapReport* snapped = nullptr, bool for_cdt = true);

}  // namespace sweepcdt::io
