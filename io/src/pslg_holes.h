// Triangle's meaning of a 2D PSLG with holes, as sweepcdt exterior notations (paper §1: a facet-
// bounded domain notates which side of each constraining segment is exterior).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "sweepcdt/plc.h"

namespace sweepcdt::io::detail {

// Triangle (-p, without -c) triangulates the convex hull, then eats triangles from the hull boundary
// inward and from every hole point outward, never across a segment. This does exactly that on
// sweepcdt's own CDT of the points and segments (cdt<2> with the convex hull as domain: exact), then
// notates each segment by which of its sides was eaten:
//   positive side eaten only -> Positive, negative side only -> Negative, neither -> None,
//   both (a segment inside a hole or outside the outer boundary) -> the segment is dropped, as
//   Triangle drops it (tags keep the input numbering).
// A PSLG without segments and holes keeps the convex hull as domain. Hole points outside the convex
// hull are ignored (as Triangle does); a hole point on a segment is an
// InputError. So is a PSLG that is not one (crossing segments, ...: core's PlcError, rephrased) and a
// domain the holes eat entirely.
void notate_from_holes(Plc<2>& plc, const std::vector<std::array<double, 2>>& holes, const std::string& file);

// The triangles of a planar PSLG after eating (the same flood): for triangulating a TetGen facet,
// given as 2D points (a projection) with its segments and hole points. Triangles counterclockwise.
std::vector<uint32_t> triangles_of_pslg(const Plc<2>& pslg, const std::vector<std::array<double, 2>>& holes, const std::string& file,
                                        const std::string& what);

}  // namespace sweepcdt::io::detail
