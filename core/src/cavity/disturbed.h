// Which tetrahedra of the Delaunay triangulation the CDT keeps (cavity_cdt.h, steps 2 and 3).
//
// A Delaunay tetrahedron T is *disturbed* by a constraining triangle c when T ∩ c is not a face of
// both: c meets T's interior, or c overlaps a face or an edge of T in their common plane, or crosses
// it. A constraint that is itself a Delaunay face disturbs nothing (the Delaunay triangulation is a
// simplicial complex). A tetrahedron disturbed by no constraint has an empty circumsphere (perturbed,
// paper §6) and meets the constraints only in common faces, so it is constrained Delaunay, and in
// general position every constrained Delaunay tetrahedron of the domain is in the CDT, when one exists.
#pragma once
#include <cstdint>
#include <vector>

#include "../steiner/delaunay3.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::detail {

struct ConstraintFaces {
  std::vector<uint32_t> of_facet;  // per facet 4 t + i of the Delaunay mesh: the constraint it is, or kNone
  std::vector<uint32_t> missing;   // the constraints that are no facet of the mesh
};

// On `threads` threads (parallel.h); the result does not depend on their number.
ConstraintFaces constraint_faces(const Plc<3>& plc, const DelaunayMesh& dt, unsigned threads);

struct Disturbed {
  std::vector<uint8_t> tets;    // per tetrahedron of the mesh: 1 when some missing constraint disturbs it
  std::vector<uint32_t> first;  // per missing constraint: one tetrahedron it disturbs
};

// Each missing constraint's disturbed tetrahedra are found by a search from the tetrahedra around one
// of its vertices (the one with the fewest) through neighbours (they are connected across facets:
// every tetrahedron holding a point of the constraint's relative interior is disturbed). Empty when
// the search finds none for a missing constraint, which would contradict that (the caller then falls
// back to a full sweep).
Disturbed disturbed_tetrahedra(const Plc<3>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& missing);

}  // namespace sweepcdt::detail
