// The CDT of a PLC from the Delaunay triangulation of its points (Algorithm::CavitySweep; beyond the
// paper, after the facet recovery by cavities of Shewchuk 2003 and Si 2008, with SWEEPCDT as the
// cavity triangulator). Said here for D = 3; the same in every dimension D = 2..5, with D-simplices
// for tetrahedra and (D-1)-simplices for constraining triangles:
//   1. the Delaunay triangulation of the points under the perturbation of paper §6 (delaunay.h);
//   2. the tetrahedra disturbed by a constraint that is no Delaunay face (disturbed.h);
//   3. the others placed inside or outside the domain by a flood fill across facets that are no
//      constraint, from the hull and from the constraints' exterior notations (domain_sides.h);
//   4. the rest of the domain — the cavities — as a PLC of its own: the facets between kept and
//      cavity tetrahedra notated with the kept side exterior, and the constraints in the cavities
//      (cavity_plc.h), one per cavity; their CDTs by SWEEPCDT (§3: sweep_cavity, below);
//   5. the kept tetrahedra and the cavities' together.
// Why that is the CDT, when the PLC has one: a kept tetrahedron has an empty (perturbed) circumsphere
// and meets the constraints only in common faces, so it is constrained Delaunay, and under the
// perturbation the CDT holds every constrained Delaunay tetrahedron of the domain (two of them never
// overlap). The CDT's tetrahedra in the cavities then triangulate the cavity PLC, and each is
// constrained Delaunay there too (more occluders, fewer points), so they are the cavity PLC's unique
// CDT, which the sweep finds (Theorem 5). The cavity PLC numbers its points in their global order, so
// the perturbation decides every tie as in the whole PLC.
// Most closed surfaces are mostly Delaunay already (a jittered sphere of 330k triangles has every
// triangle in its Delaunay triangulation), so the sweep's work shrinks to the cavities.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "../delaunay/delaunay.h"
#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

// The simplices of the CDT of a checked PLC and their neighbours (the caller validates them), or
// nullopt when this path cannot tell: fewer than D + 1 affinely independent points, a convex hull domain
// whose cavities reach the hull (cavity_plc.h), no CDT found in a cavity (then the PLC has none, and
// the whole sweep says so with its witness), or anything it did not expect. The caller then sweeps
// the whole PLC. Throws CancelledError.
// `delaunay`: the Delaunay triangulation of plc.points when the caller has it (Steiner refinement
// keeps one), else it is computed. `failed_edges`: when given, every cavity is swept even after one
// finds no CDT, and the edges of those that do not (their facets' edges, in plc's ids, in no
// particular order, repeated) are appended, and of those whose CDT does not fit the kept simplices
// around them (then the PLC has no CDT either): lazy Steiner refinement (cdt.cpp) splits there.
// `all_swept`: called once every cavity has its CDT, before they are put together with the kept
// simplices (lazy refinement frees then what it kept for another attempt).
template <int D>
std::optional<Triangulation<D>> cavity_cdt(const Plc<D>& plc, const Options& options, CdtStatistics& stats,
                                           const DelaunayMesh* delaunay = nullptr,
                                           std::vector<std::array<uint32_t, 2>>* failed_edges = nullptr,
                                           const std::function<void()>& all_swept = {});

// Step 4 for one cavity (a facet-bounded PLC): its CDT's simplices, or NoCdtError. In D = 3 by the
// sweep plane (paper §3) along the axis where the cavity's bounding box is thinnest, the axes turned
// cyclically so that it comes first (an even permutation: every orientation keeps its sign; `along`
// gets the axis). A vertex's drop face is the first face its ray along -x_1 strikes: across a thin
// or long cavity (a thin wall's, a long segment's) the ray meets the boxes of few faces, where the
// sweep sphere's rays toward its seed run along it (pipe_tee_fine: the cavity sweep 0.57 s -> 0.32
// s; 72% of its sweeps' samples were drop-face rays). Elsewhere the sweep sphere from a seed simplex
// (`along` -1). The CDT is the same either way (unique under the perturbation); the order of its
// simplices is not.
template <int D>
Triangulation<D> sweep_cavity(const Plc<D>& plc, const Options& options, CdtStatistics& stats, int* along = nullptr);

}  // namespace sweepcdt::detail
