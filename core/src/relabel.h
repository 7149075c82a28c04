// Running an algorithm under another perturbation order (paper §6) by renaming the vertices.
//
// The predicates order the perturbation by vertex id (predicates/vertex.h). Give vertex v the id
// rank[v] and every algorithm — gift-wrapping, both sweeps, the Steiner code, validate() — perturbs
// in the order `rank` without knowing it; renaming the result back gives the caller's ids. Within
// a simplex the vertices keep their places, so orientations and neighbour encodings are unchanged.
// Points beyond rank.size() (Steiner points) keep their ids.
#pragma once
#include <cstdint>
#include <vector>

#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {

// plc with point v moved to index rank[v] and every simplex renamed accordingly (same exterior
// notations, tags and region seeds: they belong to simplices and places, not to vertex ids).
template <int D>
Plc<D> relabeled(const Plc<D>& plc, const std::vector<uint32_t>& rank);

// Undo relabeled() on what was computed from its PLC: the triangulation and, if given, the PLC it
// triangulated.
template <int D>
void restore_ids(Triangulation<D>& tri, Plc<D>* triangulated, const std::vector<uint32_t>& rank);

}  // namespace sweepcdt::detail
