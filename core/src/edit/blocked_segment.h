// Whether a segment ab can be an edge of the Delaunay triangulation of a point set (3D, under the
// lifting-map perturbation of paper §6) — the deletion pass's early refusal (remove_steiner.cpp).
//
// Deleting a Steiner point v from a segment merges its two pieces av and vb into ab, which the
// cavity's CDT must then hold as an edge. Every vertex of v's star is visible from v, a point of ab
// (when v lies exactly on ab and its facets' pieces are flat: EditableCdt checks both), so when
// every sphere through a and b holds one of them, ab is not constrained Delaunay and the star sweep
// must find no CDT. That is why nearly every refusal of the pass happens (94–100% of them on 5 CAD
// parts and scans, measured before this test was built); this test says so in a few dozen insphere
// tests instead of a star sweep.
//
// The spheres through a and b are a 2-parameter family (their centres fill the bisector plane of ab;
// under the perturbation, the lifted hyperplanes through a+ and b+), and each other point c rules out
// an open half-plane of them: those that hold c. So ab is a Delaunay edge exactly when the half-planes
// left have a point in common: a 2D linear program, solved incrementally as Seidel does, with exact
// predicates only (orient, and insphere under the perturbation). The point kept is a sphere through
// a, b and two points c, d, tested against the next point e by inside_circumsphere(abcd, e); when e
// is inside, the new point lies on e's line, the spheres through a, b, e, where each point seen
// bounds the family from one side (its side of the plane abe) at the sphere through it, and the
// bounds are compared by insphere tests too. No sphere left there means none at all.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::detail {

enum class SegmentInSpheres {
  Delaunay,   // some sphere through a and b holds none of the points (ab is a Delaunay edge)
  Blocked,    // every sphere through a and b holds one of them
  Undecided,  // every point lies in one plane with a and b: not decided here
};

struct BlockedSegment {
  SegmentInSpheres answer = SegmentInSpheres::Undecided;
  // Blocked: the points that showed it, as indices into `others`: the last one met and the two
  // bounds its spheres had (or a point in its plane with a and b that all of them hold, and the
  // point off that plane the test used; or the point met three times, when it lies between a and b).
  std::array<uint32_t, 3> witness{};
};

// `others`: the points besides a and b (none equal to either), with their perturbation ids.
BlockedSegment segment_in_spheres(const predicates::Vertex& a, const predicates::Vertex& b,
                                  const std::vector<predicates::Vertex>& others);

}  // namespace sweepcdt::detail
