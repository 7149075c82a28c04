// The sequence of perturbation orders (paper §6); what each order is and why is in the header.
#include "sweepcdt/perturbation_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sweepcdt {
namespace {

constexpr int kLexicographicOrders = 4;  // orders 2..5: the sign patterns of axes 1 and 2

// SplitMix64 (Steele, Lea, Flood 2014, with the constants of Vigna's splitmix64.c): the same numbers
// on every platform and standard library.
class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }

 private:
  uint64_t state_;
};

// The order as a list of vertices, first (most perturbed) first.
template <int D>
std::vector<uint32_t> vertices_in_order(const Plc<D>& plc, int order) {
  const std::size_t n = plc.num_points();
  std::vector<uint32_t> v(n);
  std::iota(v.begin(), v.end(), 0u);
  if (order == 1) {
    std::vector<uint32_t> incident(n, 0);
    for (uint32_t id : plc.simplices)
      if (id < n) ++incident[id];  // public API: an unchecked PLC must not crash it
    std::stable_sort(v.begin(), v.end(), [&](uint32_t a, uint32_t b) { return incident[a] > incident[b]; });
  } else if (order >= 2 && order < 2 + kLexicographicOrders) {
    // Exact comparisons of the coordinates; the PLC has no two equal points (check()), and ties
    // left by an unchecked one keep the id order. A NaN would break the sort's strict weak order:
    // an unchecked PLC with one keeps the ids.
    if (!std::all_of(plc.points.begin(), plc.points.end(), [](double x) { return std::isfinite(x); })) return v;
    const int flips = order - 2;  // bit a-1: axis a (a = 1, 2) descending
    std::stable_sort(v.begin(), v.end(), [&](uint32_t a, uint32_t b) {
      for (int axis = 0; axis < D; ++axis) {
        const double x = plc.point(a)[axis], y = plc.point(b)[axis];
        if (x == y) continue;
        const bool descending = axis > 0 && axis < 3 && ((flips >> (axis - 1)) & 1);
        return descending ? x > y : x < y;
      }
      return false;
    });
  } else if (order > 0) {
    // Fisher–Yates; the modulo's bias (< n / 2^64) does not matter, only that it is reproducible.
    SplitMix64 random(static_cast<uint64_t>(order));
    for (std::size_t i = n; i > 1; --i) std::swap(v[i - 1], v[random.next() % i]);
  }
  return v;
}

}  // namespace

template <int D>
std::vector<uint32_t> perturbation_rank(const Plc<D>& plc, int order) {
  const std::vector<uint32_t> v = vertices_in_order(plc, order);
  std::vector<uint32_t> rank(v.size());
  for (uint32_t position = 0; position < v.size(); ++position) rank[v[position]] = position;
  return rank;
}

const char* perturbation_order_name(int order) {
  switch (order) {
    case 0: return "vertex ids";
    case 1: return "most constrained vertices first";
    case 2: return "coordinates, lexicographically";
    case 3: return "coordinates, lexicographically, y descending";
    case 4: return "coordinates, lexicographically, z descending";
    case 5: return "coordinates, lexicographically, y and z descending";
    default: return "pseudo-random";
  }
}

template std::vector<uint32_t> perturbation_rank<2>(const Plc<2>&, int);
template std::vector<uint32_t> perturbation_rank<3>(const Plc<3>&, int);
template std::vector<uint32_t> perturbation_rank<4>(const Plc<4>&, int);
template std::vector<uint32_t> perturbation_rank<5>(const Plc<5>&, int);

}  // namespace sweepcdt
