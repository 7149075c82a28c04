// Points placed in one refinement round, for "is one of them within r of x?" (refine.cpp: fold
// points inside facets are kept apart by half their fold's length). Floating point only chooses
// where Steiner points go, never whether the result is a CDT.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

namespace sweepcdt::detail {

class SpacingGrid {
 public:
  // Whether a point added so far lies closer than r to x (r > 0).
  bool any_within(const double* x, double r) {
    // Cells of side 2^level >= r, so a point within r is in one of the 27 cells around x's; each
    // level is filled the first time a query needs it.
    const int level = std::ilogb(r) + 1;
    auto [it, fresh] = levels_.try_emplace(level);
    if (fresh)
      for (const auto& q : points_) it->second[cell(q.data(), level)].push_back(q);
    const Cell c = cell(x, level);
    for (int64_t i = -1; i <= 1; ++i)
      for (int64_t j = -1; j <= 1; ++j)
        for (int64_t k = -1; k <= 1; ++k) {
          const auto found = it->second.find({c[0] + i, c[1] + j, c[2] + k});
          if (found == it->second.end()) continue;
          for (const auto& q : found->second)
            if (squared_distance(q.data(), x) < r * r) return true;
        }
    return false;
  }

  void add(const double* x) {
    points_.push_back({x[0], x[1], x[2]});
    for (auto& [level, cells] : levels_) cells[cell(x, level)].push_back(points_.back());
  }

 private:
  using Point = std::array<double, 3>;
  using Cell = std::array<int64_t, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return std::hash<int64_t>()(c[0] * 73856093 ^ c[1] * 19349663 ^ c[2] * 83492791);
    }
  };
  static Cell cell(const double* x, int level) {
    const auto at = [&](int k) { return static_cast<int64_t>(std::floor(std::ldexp(x[k], -level))); };
    return {at(0), at(1), at(2)};
  }
  static double squared_distance(const double* a, const double* b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
  }

  std::vector<Point> points_;
  std::map<int, std::unordered_map<Cell, std::vector<Point>, CellHash>> levels_;
};

}  // namespace sweepcdt::detail
