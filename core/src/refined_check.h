// The PLC check of a refined PLC where it can differ from the checked input (D = 3 Steiner points).
//
// refine() splits input segments at Steiner points and re-triangulates facets by flips in their
// planes. A facet all of whose points lie exactly in it — input vertices, and Steiner points exactly
// on its boundary segments, strictly inside them — is then tiled by its refined triangles, split
// alike on both sides of each segment, so its triangles meet the others only as the input facets
// did: properly (the input was checked). Only a facet holding a point rounded off its segment, or a
// point inside it, may differ from its input by rounding; check_refined() tests every pair of
// simplices that involves one of those (`suspect`), with the rest of check() (structure, duplicate
// points, degenerate and duplicate simplices) on all of them.
#pragma once
#include <vector>

#include "sweepcdt/plc.h"

namespace sweepcdt::detail {

// Throws PlcError as check() does. `suspect`: one flag per simplex of `plc`.
template <int D>
void check_refined(const Plc<D>& plc, const std::vector<char>& suspect, unsigned threads = 0);

}  // namespace sweepcdt::detail
