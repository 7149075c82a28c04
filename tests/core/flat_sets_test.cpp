// Refinement's flat sets (core/src/flat_set.h, as steiner/edge_set.h and coordinate_set.h use it).
// Their oracle is std::unordered_set, driven through the same random insert/erase/count sequence. Keys come from a
// small range, so probe runs are long, wrap around the table's end and get holes shifted back into
// them by erase().
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <random>
#include <set>
#include <unordered_set>
#include <vector>

#include "steiner/coordinate_set.h"
#include "steiner/edge_set.h"
#include "steiner/facet_groups.h"

using namespace sweepcdt;

namespace {

void edge_set_against_unordered_set(uint32_t id_range, int steps, uint32_t seed) {
  detail::EdgeSet set;
  std::unordered_set<uint64_t> oracle;
  std::mt19937 rng(seed);
  const auto random_key = [&] { return detail::edge_key(rng() % id_range, rng() % id_range); };
  for (int step = 0; step < steps; ++step) {
    const uint64_t k = random_key();
    if (rng() % 2 == 0) ASSERT_EQ(set.insert(k), oracle.insert(k).second) << "step " << step;
    else ASSERT_EQ(set.erase(k), oracle.erase(k) == 1) << "step " << step;
    ASSERT_EQ(set.size(), oracle.size());
    ASSERT_EQ(set.empty(), oracle.empty());
    if (step % 97 == 0 || id_range <= 4) {
      for (int probe = 0; probe < 64; ++probe) {
        const uint64_t q = random_key();
        ASSERT_EQ(set.count(q), oracle.count(q)) << "step " << step;
      }
      // Iteration visits each key once.
      const std::multiset<uint64_t> seen(set.begin(), set.end());
      ASSERT_EQ(seen, std::multiset<uint64_t>(oracle.begin(), oracle.end())) << "step " << step;
    }
  }
}

}  // namespace

TEST(FlatSets, EdgeSetInsertEraseCountAsUnorderedSet) {
  edge_set_against_unordered_set(12, 20000, 1);   // 78 keys: the table fills and empties many times
  edge_set_against_unordered_set(300, 20000, 2);  // sparse
  edge_set_against_unordered_set(4, 5000, 3);     // 10 keys in a 16-slot table: runs wrap around
}

TEST(FlatSets, EdgeSetEraseKeepsEveryProbeRunWhole) {
  // Keys erased in every order from a table they fill to three quarters: each other one is still found.
  std::vector<uint64_t> keys;
  for (uint32_t a = 0; a < 5; ++a)
    for (uint32_t b = a + 1; b < 5; ++b) keys.push_back(detail::edge_key(a, b));  // 10 keys, 16 slots
  keys.push_back(detail::edge_key(0, 0));
  keys.push_back(detail::edge_key(7, 7));
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    detail::EdgeSet set(keys.begin(), keys.end());
    ASSERT_EQ(set.size(), keys.size());
    std::vector<uint64_t> order = keys;
    std::shuffle(order.begin(), order.end(), rng);
    for (std::size_t i = 0; i < order.size(); ++i) {
      ASSERT_TRUE(set.erase(order[i]));
      ASSERT_FALSE(set.erase(order[i]));
      for (std::size_t j = 0; j < order.size(); ++j) ASSERT_EQ(set.count(order[j]), j > i ? 1u : 0u) << "trial " << trial;
    }
    ASSERT_TRUE(set.empty());
    ASSERT_EQ(set.begin(), set.end());
  }
}

TEST(FlatSets, CoordinateSetFindsPointsBitForBit) {
  // Points on a small grid, and the same with -0.0 for 0.0: bit for bit, they differ.
  detail::CoordinateSet set;
  std::unordered_set<std::array<uint64_t, 3>, decltype([](const std::array<uint64_t, 3>& k) {
                       return std::hash<uint64_t>()(k[0] * 31 + k[1] * 17 + k[2]);
                     })>
      oracle;
  std::mt19937 rng(11);
  const auto bits = [](const double* x) {
    return std::array<uint64_t, 3>{std::bit_cast<uint64_t>(x[0]), std::bit_cast<uint64_t>(x[1]), std::bit_cast<uint64_t>(x[2])};
  };
  const auto random_point = [&](double* x) {
    for (int k = 0; k < 3; ++k) x[k] = static_cast<double>(static_cast<int>(rng() % 7) - 3) * 0.5;
    if (rng() % 4 == 0) x[rng() % 3] = -0.0;
  };
  for (int step = 0; step < 5000; ++step) {
    double x[3];
    random_point(x);
    if (rng() % 3 != 0) {
      set.insert(x);
      oracle.insert(bits(x));
    }
    double q[3];
    random_point(q);
    ASSERT_EQ(set.contains(q), oracle.count(bits(q)) == 1) << "step " << step;
    ASSERT_EQ(set.empty(), oracle.empty());
  }
  const double zero[3] = {0.0, 0.0, 0.0}, negative_zero[3] = {-0.0, 0.0, 0.0};
  detail::CoordinateSet one;
  one.reserve(1);
  one.insert(zero);
  EXPECT_TRUE(one.contains(zero));
  EXPECT_FALSE(one.contains(negative_zero));
}
