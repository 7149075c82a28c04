// The triangles to show a user whose surface does not bound a volume (MeshLab selects them): the
// triangles of every problem a SurfaceReport lists.
#pragma once
#include <cstdint>
#include <vector>

#include "sweepcdt/io/surface.h"

namespace sweepcdt::io {

// Sorted, distinct triangle indices of `surface`: for a boundary or non-manifold edge, every triangle
// with that edge; for a pinched vertex, every triangle at it; for the other kinds, the triangles the
// problem names. Only the problems the report lists count: inspect(surface, SIZE_MAX) lists them all.
std::vector<uint32_t> problem_triangles(const Surface& surface, const SurfaceReport& report);

// Sorted triangle indices of `surface` with a corner among `vertices` (e.g. a NoCdtError's witness;
// ids beyond the surface's points, such as Steiner points, are ignored).
std::vector<uint32_t> triangles_at_vertices(const Surface& surface, std::vector<uint32_t> vertices);

}  // namespace sweepcdt::io
