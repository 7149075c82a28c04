// A brute-force reference for small inputs: the Delaunay triangulation of the perturbed points
// (paper §6) as the set of all (D+1)-subsets whose perturbed circumsphere holds no other point.
// O(n^{D+2}) — an algorithm entirely unlike validate()'s local test, so each checks the other.
#pragma once
#include <algorithm>
#include <vector>

#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::fixtures {

template <int D>
Triangulation<D> brute_force_delaunay(const std::vector<double>& points) {
  Triangulation<D> tri;
  tri.points = points;
  tri.num_input_points = static_cast<uint32_t>(points.size() / D);
  const uint32_t n = tri.num_input_points;
  std::vector<uint32_t> pick(D + 1);
  // Enumerate subsets in lexicographic order.
  std::vector<bool> mask(n, false);
  std::fill(mask.begin(), mask.begin() + std::min<uint32_t>(n, D + 1), true);
  if (n < D + 1) return tri;
  do {
    for (uint32_t i = 0, k = 0; i < n; ++i)
      if (mask[i]) pick[k++] = i;
    predicates::Vertices<D + 1> s;
    for (int i = 0; i <= D; ++i) s[i] = {tri.point(pick[i]), pick[i]};
    const auto o = predicates::orient<D>(predicates::coords_of(s));
    if (o == predicates::Sign::Zero) continue;
    bool empty = true;
    for (uint32_t q = 0; q < n && empty; ++q) {
      if (std::find(pick.begin(), pick.end(), q) != pick.end()) continue;
      empty = !predicates::inside_circumsphere<D>(s, {tri.point(q), q});
    }
    if (!empty) continue;
    if (o == predicates::Sign::Negative) std::swap(pick[0], pick[1]);
    tri.simplices.insert(tri.simplices.end(), pick.begin(), pick.end());
  } while (std::prev_permutation(mask.begin(), mask.end()));
  compute_neighbors(tri);
  return tri;
}

}  // namespace sweepcdt::fixtures
