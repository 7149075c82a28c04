#include "box_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sweepcdt::cli {

BoxGrid::BoxGrid(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
  std::array<double, 3> high;
  low_.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for (const Box& b : boxes_)
    for (int c = 0; c < 3; ++c) {
      low_[c] = std::min(low_[c], b[c]);
      high[c] = std::max(high[c], b[3 + c]);
    }
  cells_ = std::max(1, static_cast<int>(std::cbrt(static_cast<double>(boxes_.size()))));
  for (int c = 0; c < 3; ++c) scale_[c] = high[c] > low_[c] ? cells_ / (high[c] - low_[c]) : 0.0;
  grid_.resize(std::size_t(cells_) * cells_ * cells_);
  for (uint32_t j = 0; j < boxes_.size(); ++j) {
    std::array<int, 3> a, b;
    for (int c = 0; c < 3; ++c) a[c] = cell(c, boxes_[j][c]), b[c] = cell(c, boxes_[j][3 + c]);
    for (int x = a[0]; x <= b[0]; ++x)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int z = a[2]; z <= b[2]; ++z) grid_[index(x, y, z)].push_back(j);
  }
}

const std::vector<uint32_t>& BoxGrid::near(const double* p) const {
  static const std::vector<uint32_t> none;
  if (boxes_.empty()) return none;
  return grid_[index(cell(0, p[0]), cell(1, p[1]), cell(2, p[2]))];
}

bool BoxGrid::holds(uint32_t box, const double* p) const {
  for (int c = 0; c < 3; ++c)
    if (p[c] < boxes_[box][c] || p[c] > boxes_[box][3 + c]) return false;
  return true;
}

// Monotone in x (clamped to the grid), so a box holding p overlaps p's cell. A NaN goes to cell 0
// (no box holds it).
int BoxGrid::cell(int axis, double x) const {
  const double f = std::floor((x - low_[axis]) * scale_[axis]);
  return !(f >= 0) ? 0 : f >= cells_ ? cells_ - 1 : static_cast<int>(f);
}

}  // namespace sweepcdt::cli
