// Does a constraining (D-1)-simplex t meet the interior of a D-simplex s? (The growth rule of
// gift-wrapping, paper §2: the new simplex's interior must meet no constraining facet.)
//
// The open simplex int(s) and the closed simplex t are disjoint iff some hyperplane weakly separates
// them, and then one does that passes through D affinely independent vertices of s and t (an extreme
// ray of the cone of separating hyperplanes, which is pointed because s spans E^D). So the test
// tries every such hyperplane with orientation predicates only: exact, any dimension, C(2D+1, D)
// candidate hyperplanes (35 in 3D).
#pragma once
#include <array>
#include <cstdint>

namespace sweepcdt::detail {

// `outer_facet`, when given, is set to i for the facet of s without vertex i whose hyperplane has t
// on its closed outer side, when the answer came from such a facet (the quick answer, the usual
// one), else to -1. Then t meets s only in that facet.
template <int D>
bool interior_meets(const std::array<const double*, D + 1>& s, const std::array<const double*, D>& t, int* outer_facet = nullptr);

}  // namespace sweepcdt::detail
