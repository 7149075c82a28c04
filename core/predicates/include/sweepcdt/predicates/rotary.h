// Rotary order of (D-1)-faces around a shared ridge (a (D-2)-face), for the ridges' circular lists
// in SWEEPCDT (paper §3, Figure 12).
//
// A face around ridge r is given by its apex a (the face is conv(r ∪ a)). Angles are measured from a
// reference apex `ref`, turning in the direction in which orient(r, ref, x) > 0; so the faces with
// orient(r, ref, x) > 0 come in the first half-turn, those with orient(r, ref, x) < 0 in the second,
// and a face coplanar with ref's face is at angle 0 (same side of r) or exactly a half-turn.
#pragma once
#include "sweepcdt/predicates/sign.h"
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

// Negative when the face with apex a comes before the face with apex b, Zero at equal angles.
template <int D>
Sign compare_rotary(const Coords<D - 1>& ridge, const double* ref, const double* a, const double* b);

// Both a and b lie in the hyperplane through `ridge` and `a` (so orient(ridge, a, b) = 0):
// are they on the same side of the ridge within that hyperplane?
template <int D>
bool same_side_of_ridge(const Coords<D - 1>& ridge, const double* a, const double* b);

}  // namespace sweepcdt::predicates
