// Small helpers shared by the tests: a triangulation's simplices as a comparable set, and random
// distinct points on an integer grid (exact degeneracies everywhere).
#pragma once
#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "sweepcdt/triangulation.h"

namespace sweepcdt::fixtures {

// Each simplex as its sorted vertex ids: equal sets mean the same triangulation.
template <int D>
std::set<std::vector<uint32_t>> simplex_set(const Triangulation<D>& tri) {
  std::set<std::vector<uint32_t>> set;
  for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
    std::vector<uint32_t> s(tri.simplex(t), tri.simplex(t) + D + 1);
    std::sort(s.begin(), s.end());
    set.insert(s);
  }
  return set;
}

// `count` distinct points with integer coordinates in [0, grid], as D-tuples in one vector.
template <int D>
std::vector<double> distinct_grid_points(std::mt19937_64& rng, int count, int grid) {
  std::set<std::vector<double>> seen;
  std::vector<double> points;
  std::uniform_int_distribution<int> coordinate(0, grid);
  while (static_cast<int>(seen.size()) < count) {
    std::vector<double> p(D);
    for (auto& x : p) x = coordinate(rng);
    if (seen.insert(p).second) points.insert(points.end(), p.begin(), p.end());
  }
  return points;
}

// Insertion orders of n points for tests whose result must not depend on the order: index order,
// reverse order, and `random` shuffles (seeded by n, so reproducible).
inline std::vector<std::vector<uint32_t>> insertion_orders(uint32_t n, int random) {
  std::vector<uint32_t> order(n);
  for (uint32_t i = 0; i < n; ++i) order[i] = i;
  std::vector<std::vector<uint32_t>> orders{order, std::vector<uint32_t>(order.rbegin(), order.rend())};
  std::mt19937_64 rng(n);
  for (int k = 0; k < random; ++k) {
    std::shuffle(order.begin(), order.end(), rng);
    orders.push_back(order);
  }
  return orders;
}

}  // namespace sweepcdt::fixtures
