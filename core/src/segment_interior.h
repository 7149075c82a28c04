// Whether a point lies exactly inside a segment (exact: no tolerance).
#pragma once
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::detail {

// x on the line of a and b (predicates::collinear), strictly between them: along an axis where a
// and b differ, x's coordinate is strictly between theirs (on the line, one such axis decides).
template <int D>
bool strictly_inside_segment(const double* a, const double* x, const double* b) {
  if (!predicates::collinear<D>(a, x, b)) return false;
  for (int k = 0; k < D; ++k)
    if (a[k] != b[k]) return (a[k] < x[k] && x[k] < b[k]) || (b[k] < x[k] && x[k] < a[k]);
  return false;  // a = b
}

}  // namespace sweepcdt::detail
