// The perturbation orders cdt() tries (paper §6), as a fixed sequence anyone can reproduce —
// `sweepcdt check` does, to validate a mesh made under a later order.
//
// Paper §6 perturbs the lifted vertices "in some arbitrary order", the first one most. When d+2 or
// more vertices are exactly cospherical the order decides which of their triangulations the
// perturbed CDT contains — the one that pulls the group's earliest vertex (joins it to all it sees;
// on a flat face of the hull, each cocircular polygon is fanned from its earliest vertex) — and so
// whether the perturbed PLC has a CDT at all: a cube whose face diagonals fix its tetrahedralization
// has one only when a vertex on three diagonals comes first and the far faces' diagonals agree.
// "The order in which the vertices are perturbed can determine whether or not a triangulation is
// discovered." Which order works is not known in advance, hence a sequence:
//
//   order 0     vertex ids (the identity)                     — every run starts with it
//   order 1     vertices on the most constraining simplices first, ties by id: a vertex where face
//               diagonals meet is one the boundary wants pulled first (a cube's corner on three
//               diagonals, a prism's corner on two)
//   orders 2-5  coordinates lexicographically (paper §6's own example), x ascending, y and z each
//               ascending or descending: every axis-parallel square then gets the diagonal through its
//               least corner in that sense, so a grid of cubes whose squares are all split the same
//               way (all along (1,1), say) gets a CDT from one of them
//   order 6+    pseudo-random permutations: SplitMix64 seeded with the order number, Fisher–Yates —
//               written out, because std::shuffle and std::uniform_int_distribution differ between
//               standard libraries and the sequence must not
//
// Every order is a function of the PLC alone (its ids, constraining simplices and coordinates), so
// anyone with the PLC can reproduce it.
//
// rank[v] is vertex v's position in the order: the perturbation treats v as if its id were rank[v]
// (lower rank = larger perturbation; Triangulation::perturbation_rank records it).
#pragma once
#include <cstdint>
#include <vector>

#include "sweepcdt/plc.h"

namespace sweepcdt {

// How many orders cdt() tries at most: each try is a full run, so a PLC that has no CDT under any
// of them costs this many runs (cdt() stops early when a run met no exact tie; see cdt.h).
inline constexpr int kPerturbationOrders = 8;

// rank (a permutation of 0 .. plc.num_points()-1) of order `order` (0 <= order, any value works).
template <int D>
std::vector<uint32_t> perturbation_rank(const Plc<D>& plc, int order);

// What order `order` is, in a few words ("vertex ids", "most constrained vertices first", ...).
const char* perturbation_order_name(int order);

}  // namespace sweepcdt
