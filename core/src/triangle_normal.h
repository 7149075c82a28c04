// A triangle's normal in floating point, for choosing a projection only: the least distorted one
// drops the axis of the normal's largest component. Every orientation tested in that projection is
// exact; the choice of axis decides only which tests are made.
#pragma once
#include <cmath>

namespace sweepcdt::detail {

// Component `axis` of (b - a) x (c - a).
inline double normal_component(const double* a, const double* b, const double* c, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  return (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
}

// The axis of the largest component of triangle abc's normal (the first of equal ones).
inline int dominant_axis(const double* a, const double* b, const double* c) {
  int best = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (std::abs(normal_component(a, b, c, axis)) > std::abs(normal_component(a, b, c, best))) best = axis;
  return best;
}

}  // namespace sweepcdt::detail
