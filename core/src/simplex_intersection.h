// Exact tests of whether two constraining (D-1)-simplices of a PLC meet other than in the face their
// shared vertices span (the PLC condition of paper §1). D = 2 and D = 3 are decided by orientation
// predicates; D >= 4 by an exact rational linear program (simplex_intersection_lp), which the tests
// also use as the reference for D = 2, 3.
#pragma once
#include <array>
#include <cstdint>

namespace sweepcdt::detail {

// a, b: the simplices' vertex coordinates; ida, idb: their vertex ids (equal ids = shared vertex).
// Both simplices must be non-degenerate and distinct points must have distinct ids.
template <int D>
bool improper_intersection(const std::array<const double*, D>& a, const std::array<uint32_t, D>& ida,
                           const std::array<const double*, D>& b, const std::array<uint32_t, D>& idb);

// The same decided by linear programming over the rationals, in any dimension.
template <int D>
bool improper_intersection_lp(const std::array<const double*, D>& a, const std::array<uint32_t, D>& ida,
                              const std::array<const double*, D>& b, const std::array<uint32_t, D>& idb);

// Does point p lie in the closed (D-1)-simplex f (non-degenerate)?
template <int D>
bool point_in_simplex(const double* p, const std::array<const double*, D>& f);

}  // namespace sweepcdt::detail
