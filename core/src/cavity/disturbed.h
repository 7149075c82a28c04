// Which simplices of the Delaunay triangulation the CDT keeps (cavity_cdt.h, steps 2 and 3). In 3D:
//
// A Delaunay tetrahedron T is *disturbed* by a constraining triangle c when T ∩ c is not a face of
// both: c meets T's interior, or c overlaps a face or an edge of T in their common plane, or crosses
// it. A constraint that is itself a Delaunay face disturbs nothing (the Delaunay triangulation is a
// simplicial complex). A tetrahedron disturbed by no constraint has an empty circumsphere (perturbed,
// paper §6) and meets the constraints only in common faces, so it is constrained Delaunay, and in
// general position every constrained Delaunay tetrahedron of the domain is in the CDT, when one exists.
// The same holds in every dimension D for D-simplices and constraining (D-1)-simplices; D = 2..5.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "../delaunay/delaunay.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::detail {

struct ConstraintFaces {
  std::vector<uint32_t> of_facet;  // per facet (D+1) t + i of the Delaunay mesh: the constraint it is, or kNone
  std::vector<uint32_t> missing;   // the constraints that are no facet of the mesh
};

// On `threads` threads (parallel.h); the result does not depend on their number.
template <int D>
ConstraintFaces constraint_faces(const Plc<D>& plc, const DelaunayMesh& dt, unsigned threads);

struct Disturbed {
  std::vector<uint8_t> tets;    // per simplex of the mesh: 1 when some missing constraint disturbs it
  std::vector<uint32_t> first;  // per missing constraint: one simplex it disturbs
};

// Each missing constraint's disturbed simplices are found by a search from one of them, found among
// the simplices around one of its vertices (the one with the fewest), through neighbours (they are
// connected across facets: every simplex holding a point of the constraint's relative interior is
// disturbed; in 3D the search crosses only the facets the constraint meets improperly). Empty when
// the search finds none for a missing constraint, which would contradict that (the caller then falls
// back to a full sweep). The constraints are searched in parts on `threads` threads (parallel.h),
// kConstraintsPerThread at least a part; the result does not depend on their number.
//
// A search costs a few microseconds (the OpenSCAD thread of bench/run_cad.py --scad: 41341 missing
// constraints in 0.11 s on two threads; 0.3 s before the search crossed only facets, and a fifth
// of the run on one thread before that): a few hundred make a part worth a thread.
inline constexpr std::size_t kConstraintsPerThread = 256;
template <int D>
Disturbed disturbed_simplices(const Plc<D>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& missing, unsigned threads);

}  // namespace sweepcdt::detail
