#include "simplex_interior.h"

#include <algorithm>
#include <array>

#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::detail {

using predicates::Sign;

template <int D>
bool interior_meets(const std::array<const double*, D + 1>& s, const std::array<const double*, D>& t, int* outer_facet) {
  if (outer_facet) *outer_facet = -1;
  // Quick answer first: t lies on the closed outer side of a facet hyperplane of s (the usual case).
  const Sign inner = predicates::orient<D>(s);  // s's own orientation: each vertex's side of its facet
  for (int facet = 0; facet <= D; ++facet) {
    predicates::Coords<D + 1> plane = s;
    bool outside = true;
    for (int k = 0; k < D && outside; ++k) {
      plane[facet] = t[k];
      outside = predicates::orient<D>(plane) != inner;
    }
    if (outside) {
      if (outer_facet) *outer_facet = facet;
      return false;
    }
  }
  // Each distinct point once, with its membership: a shared vertex (same pointer into the point
  // array) constrains the sides of both simplices.
  std::array<const double*, 2 * D + 1> points{};
  std::array<char, 2 * D + 1> in_s{}, in_t{};
  int n = D + 1;
  for (int i = 0; i <= D; ++i) points[i] = s[i], in_s[i] = 1;
  for (const double* p : t) {
    const auto it = std::find(points.begin(), points.begin() + n, p);
    if (it != points.begin() + n) {
      in_t[it - points.begin()] = 1;
    } else {
      points[n] = p;
      in_t[n++] = 1;
    }
  }

  std::array<int, D> pick;
  for (int i = 0; i < D; ++i) pick[i] = i;
  for (;;) {
    predicates::Coords<D + 1> plane;
    for (int i = 0; i < D; ++i) plane[i] = points[pick[i]];
    // Side of every point; the hyperplane must be spanned (some point off it: s spans E^D).
    bool s_negative = false, s_positive = false, t_negative = false, t_positive = false;
    for (int k = 0; k < n; ++k) {
      if (std::find(pick.begin(), pick.end(), k) != pick.end()) continue;  // on the plane by construction
      plane[D] = points[k];
      const Sign side = predicates::orient<D>(plane);
      if (in_s[k]) s_negative |= side == Sign::Negative, s_positive |= side == Sign::Positive;
      if (in_t[k]) t_negative |= side == Sign::Negative, t_positive |= side == Sign::Positive;
    }
    const bool spanned = s_negative || s_positive;
    if (spanned && ((!s_positive && !t_negative) || (!s_negative && !t_positive))) return false;
    // Next D-subset in lexicographic order.
    int i = D - 1;
    while (i >= 0 && pick[i] == n - D + i) --i;
    if (i < 0) return true;
    ++pick[i];
    for (int j = i + 1; j < D; ++j) pick[j] = pick[j - 1] + 1;
  }
}

template bool interior_meets<2>(const std::array<const double*, 3>&, const std::array<const double*, 2>&, int*);
template bool interior_meets<3>(const std::array<const double*, 4>&, const std::array<const double*, 3>&, int*);
template bool interior_meets<4>(const std::array<const double*, 5>&, const std::array<const double*, 4>&, int*);
template bool interior_meets<5>(const std::array<const double*, 6>&, const std::array<const double*, 5>&, int*);

}  // namespace sweepcdt::detail
