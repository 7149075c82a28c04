// Nesting of closed shells, decided exactly (used by inspect() on valid surfaces).
#pragma once
#include <cstdint>
#include <vector>

#include "sweepcdt/io/surface.h"

namespace sweepcdt::io::detail {

// Is point q strictly inside the closed shell given by `triangles` (indices into surface.triangles)?
// Ray parity along +x with the ray symbolically perturbed to q + (0, e, e^2), so the perturbed ray
// meets no vertex or edge and every crossing is decided by exact orientation signs. q must not lie
// on the shell.
bool inside_shell(const Surface& surface, const std::vector<uint32_t>& triangles, const double* q);

// Sign (+1, -1) of the volume enclosed by a closed shell whose triangle t is taken reversed when
// reversed[t]: positive when the triangles are counterclockwise seen from outside. Exact.
int volume_sign(const Surface& surface, const std::vector<uint32_t>& triangles, const std::vector<uint8_t>& reversed);

// Fills parent and depth of every shell (all closed, disjoint, non-intersecting): shell A lies in
// shell B iff a vertex of A is inside B.
void nest_shells(const Surface& surface, const std::vector<std::vector<uint32_t>>& shell_triangles, std::vector<Shell>& shells);

}  // namespace sweepcdt::io::detail
