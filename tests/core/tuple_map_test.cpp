// TupleMap (core/src/tuple_map.h): the flat hash map of faces. Its oracle is std::unordered_map,
// driven through the same random emplace/erase/find sequence. Keys come from a small range, so probe
// runs are long, wrap around the table's end and get holes shifted back into them by erase().
#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

#include "facet_hash.h"
#include "tuple_map.h"

using namespace sweepcdt;

namespace {

template <std::size_t N>
void run_against_unordered_map(uint32_t key_range, int steps, uint32_t seed) {
  using Key = std::array<uint32_t, N>;
  detail::TupleMap<N> map(4);
  std::unordered_map<Key, uint32_t, detail::TupleHash> oracle;
  std::mt19937 rng(seed);
  const auto random_key = [&] {
    Key k;
    for (auto& x : k) x = rng() % key_range;
    return k;
  };
  for (int step = 0; step < steps; ++step) {
    const Key k = random_key();
    switch (rng() % 3) {
      case 0: {
        const uint32_t value = rng() % 1000;
        const auto [stored, inserted] = map.emplace(k, value);
        const auto [it, oracle_inserted] = oracle.emplace(k, value);
        ASSERT_EQ(inserted, oracle_inserted) << "step " << step;
        ASSERT_EQ(stored, it->second) << "step " << step;
        break;
      }
      case 1:
        ASSERT_EQ(map.erase(k), oracle.erase(k) == 1) << "step " << step;
        break;
      default:
        break;
    }
    ASSERT_EQ(map.size(), oracle.size());
    // Every key of the range is found exactly when the oracle has it (the whole range when small).
    if (step % 97 == 0 || key_range <= 4) {
      for (int probe = 0; probe < 64; ++probe) {
        const Key q = random_key();
        const auto it = oracle.find(q);
        ASSERT_EQ(map.find(q), it == oracle.end() ? detail::TupleMap<N>::kAbsent : it->second) << "step " << step;
        ASSERT_EQ(map.contains(q), it != oracle.end());
      }
      for (const auto& [key, value] : oracle) ASSERT_EQ(map.find(key), value) << "step " << step;
    }
  }
}

}  // namespace

TEST(TupleMap, EmplaceEraseFindAsUnorderedMap) {
  run_against_unordered_map<3>(6, 20000, 1);     // 216 keys: the table fills and empties many times
  run_against_unordered_map<3>(40, 20000, 2);    // sparse
  run_against_unordered_map<2>(4, 5000, 3);      // 16 keys in a 16- or 32-slot table: runs wrap around
  run_against_unordered_map<4>(5, 20000, 4);
  run_against_unordered_map<1>(300, 20000, 5);  // single ids: EditableCdt's sets of a star's simplices and vertices
}

TEST(TupleMap, EraseKeepsEveryProbeRunWhole) {
  // Keys erased in every order from a full run: each of the others is still found.
  using Key = std::array<uint32_t, 3>;
  std::vector<Key> keys;
  for (uint32_t a = 0; a < 6; ++a)
    for (uint32_t b = a + 1; b < 7; ++b) keys.push_back({a, b, b + 1});
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    detail::TupleMap<3> map(4);
    for (uint32_t i = 0; i < keys.size(); ++i) map.emplace(keys[i], i);
    std::vector<uint32_t> order(keys.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<char> gone(keys.size(), 0);
    for (const uint32_t e : order) {
      ASSERT_TRUE(map.erase(keys[e]));
      ASSERT_FALSE(map.erase(keys[e]));
      gone[e] = 1;
      for (uint32_t i = 0; i < keys.size(); ++i) ASSERT_EQ(map.find(keys[i]), gone[i] ? detail::TupleMap<3>::kAbsent : i);
    }
    ASSERT_EQ(map.size(), 0u);
  }
}

// clear() (a map reused for many small sets, editable_cdt.cpp): empty afterwards, its capacity kept,
// and filled again like a new one.
TEST(TupleMap, ClearedMapIsEmptyAndFillsAgain) {
  detail::TupleMap<1> map(4);
  for (uint32_t round = 0; round < 3; ++round) {
    for (uint32_t i = 0; i < 100; ++i) ASSERT_TRUE(map.emplace({7 * i + round}, i).second);
    for (uint32_t i = 0; i < 100; ++i) ASSERT_FALSE(map.emplace({7 * i + round}, 0).second);
    ASSERT_EQ(map.size(), 100u);
    const std::size_t capacity = map.capacity();
    map.clear();
    EXPECT_EQ(map.size(), 0u);
    EXPECT_EQ(map.capacity(), capacity);
    for (uint32_t i = 0; i < 100; ++i) ASSERT_FALSE(map.contains({7 * i + round}));
  }
}
