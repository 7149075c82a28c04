// Steiner points so that a CDT exists (issue 7, beyond the paper): Shewchuk's companion result — a
// PLC has a CDT when every segment (edge of a constraining triangle) is strongly Delaunay. Edges
// that are not edges of the (perturbed) Delaunay triangulation of the current points are split at
// their midpoints, the triangles holding them split in two, until every edge is Delaunay.
//
// Exactness: a midpoint is computed in floating point, so it lies on its segment only as closely as
// rounding allows (each coordinate within half an ulp of the exact midpoint); the refined PLC is
// checked exactly, and the CDT is of the refined PLC. Termination: midpoint splitting can cascade —
// splitting an edge of a skinny triangle adds a long median that may not be Delaunay in turn, which
// happens on many real surfaces — so rounds, growth and the number of Steiner points are bounded
// and exceeding them is a NoCdtError that says so. Refinement with protected vertices and points
// inside triangles is the planned cure.
#pragma once
#include <cstdint>
#include <vector>

#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

struct RefinedPlc {
  Plc<3> plc;                         // the input's points first, then the Steiner points
  uint32_t num_input_points = 0;
  std::vector<uint32_t> steiner_on;   // per Steiner point: an input triangle (index) it lies on
  std::vector<uint32_t> original;     // per refined triangle: the input triangle it is part of
  int rounds = 0;
};

RefinedPlc recover_segments(const Plc<3>& input, const Options& options);

}  // namespace sweepcdt::detail
