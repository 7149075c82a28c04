// Visibility (paper §1): the visibility between p and q is occluded by a constraining
// (D-1)-simplex t if p and q lie strictly on opposite sides of t's hyperplane and the segment pq
// meets t, in its relative interior or on its boundary. An endpoint in t's hyperplane never occludes.
#pragma once
#include "sweepcdt/predicates/vertex.h"

namespace sweepcdt::predicates {

template <int D>
bool occludes(const Coords<D>& t, const double* p, const double* q);

}  // namespace sweepcdt::predicates
