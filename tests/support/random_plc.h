// Small random constrained PLCs on the integer grid (exact degeneracies everywhere), for the tests
// that compare algorithms with the brute-force oracle (brute_force_cdt.h).
#pragma once
#include <random>
#include <set>
#include <vector>

#include "sweepcdt/plc.h"

namespace sweepcdt::fixtures {

// `inner` points on the grid {1,2,3}^D, `outer` on {0,..,4}^D (all distinct): the constraints are
// drawn among the inner points, so they lie in the middle with vertices on both sides of them.
template <int D>
Plc<D> random_constrained_plc(std::mt19937_64& rng, int inner, int outer, int constraints) {
  Plc<D> plc;
  std::set<std::vector<double>> seen;
  auto draw = [&](int count, int lo, int hi) {
    std::uniform_int_distribution<int> coordinate(lo, hi);
    for (int drawn = 0; drawn < count;) {
      std::vector<double> p(D);
      for (auto& x : p) x = coordinate(rng);
      if (seen.insert(p).second) plc.points.insert(plc.points.end(), p.begin(), p.end()), ++drawn;
    }
  };
  draw(inner, 1, 3);
  draw(outer, 0, 4);
  std::uniform_int_distribution<uint32_t> pick(0, static_cast<uint32_t>(inner - 1));
  for (int tries = 0; tries < 200 && static_cast<int>(plc.num_simplices()) < constraints; ++tries) {
    std::vector<uint32_t> c(D);
    for (auto& x : c) x = pick(rng);
    plc.simplices.insert(plc.simplices.end(), c.begin(), c.end());
    if (!find_problems(plc).empty()) plc.simplices.resize(plc.simplices.size() - D);
  }
  return plc;
}

}  // namespace sweepcdt::fixtures
