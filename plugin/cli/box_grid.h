// Which of many closed axis-aligned boxes may hold a point: a uniform grid of about one cell per
// box, so that `sweepcdt check` does not test every Steiner point against every input edge.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sweepcdt::cli {

using Box = std::array<double, 6>;  // low x y z, high x y z

class BoxGrid {
 public:
  explicit BoxGrid(std::vector<Box> boxes);
  // The boxes that overlap p's cell, ascending: every box holding p is among them.
  const std::vector<uint32_t>& near(const double* p) const;
  bool holds(uint32_t box, const double* p) const;

 private:
  int cell(int axis, double x) const;
  std::size_t index(int x, int y, int z) const { return (std::size_t(x) * cells_ + y) * cells_ + z; }

  std::vector<Box> boxes_;
  std::array<double, 3> low_{}, scale_{};
  int cells_ = 1;
  std::vector<std::vector<uint32_t>> grid_;
};

// The box of points given by ids into `points` (n x 3).
template <class Ids>
Box box_of(const std::vector<double>& points, const Ids& ids) {
  Box b;
  for (int c = 0; c < 3; ++c) b[c] = b[3 + c] = points[3 * std::size_t{*ids.begin()} + c];
  for (uint32_t v : ids)
    for (int c = 0; c < 3; ++c) {
      const double x = points[3 * std::size_t{v} + c];
      if (x < b[c]) b[c] = x;
      if (x > b[3 + c]) b[3 + c] = x;
    }
  return b;
}

}  // namespace sweepcdt::cli
