// Internal: is a point the rounded split of two points of a set (the fold points of
// surface_points.h)? Trying every pair costs k²/2 exact tests for k points, for every fold point of
// a facet; this search gives the same answer on every input in O(k log k) plus the pairs it cannot
// rule out (split_of_two.cpp says which, and why none that splits is missed).
#pragma once
#include <cstdint>
#include <span>

namespace sweepcdt::detail {

// `points`: n x 3. True iff is_point_on_segment(a, b, s) (sweepcdt/steiner_point.h) for some two
// of `candidates` (ids into `points`; s need not be excluded: no point splits a pair with itself).
bool is_split_of_two(std::span<const double> points, uint32_t s, std::span<const uint32_t> candidates);

}  // namespace sweepcdt::detail
