#include "sweepcdt/io/snap.h"

#include "sweepcdt/predicates/orientation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace sweepcdt::io {
namespace {

struct Value {
  double x;
  uint64_t count;  // points with this coordinate
};

// Distinct coordinates along `axis`, ascending, with their counts.
std::vector<Value> distinct_values(const std::vector<double>& points, int axis) {
  std::vector<double> xs;
  for (std::size_t i = axis; i < points.size(); i += 3) xs.push_back(points[i]);
  std::sort(xs.begin(), xs.end());
  std::vector<Value> values;
  for (const double x : xs) {
    if (values.empty() || values.back().x != x) values.push_back({x, 0});
    ++values.back().count;
  }
  return values;
}

// The value a cluster [first, last) becomes: the most frequent, then the least magnitude, then the smaller.
double representative(std::vector<Value>::const_iterator first, std::vector<Value>::const_iterator last) {
  return std::min_element(first, last, [](const Value& a, const Value& b) {
           if (a.count != b.count) return a.count > b.count;
           if (std::abs(a.x) != std::abs(b.x)) return std::abs(a.x) < std::abs(b.x);
           return a.x < b.x;
         })->x;
}

// What each distinct value becomes: greedy clusters of values within `tolerance` of their smallest.
std::vector<double> snapped_values(const std::vector<Value>& v, double tolerance) {
  std::vector<double> becomes(v.size());
  for (std::size_t first = 0; first < v.size();) {
    std::size_t last = first + 1;
    while (last < v.size() && v[last].x - v[first].x <= tolerance) ++last;
    std::fill(becomes.begin() + first, becomes.begin() + last, representative(v.begin() + first, v.begin() + last));
    first = last;
  }
  return becomes;
}

// Edges with exactly two triangles whose four points are exactly coplanar in `after` but not in
// `before` (the same triangles, welded differently).
uint64_t edges_flattened(const Surface& before, const Surface& after) {
  struct Side {
    uint32_t a, b, triangle;  // edge a < b of `triangle` in `before`
  };
  std::vector<Side> sides;
  for (uint32_t t = 0; t < before.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = before.triangles[3 * t + k], b = before.triangles[3 * t + (k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), t});
    }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) { return std::tie(x.a, x.b, x.triangle) < std::tie(y.a, y.b, y.triangle); });
  // Whether t's corners and corner `k` of u are exactly coplanar in `s`.
  const auto coplanar = [](const Surface& s, uint32_t t, uint32_t u, int k) {
    const auto p = [&](uint32_t triangle, int corner) { return s.points.data() + 3 * std::size_t{s.triangles[3 * triangle + corner]}; };
    return predicates::orient<3>({p(t, 0), p(t, 1), p(t, 2), p(u, k)}) == predicates::Sign::Zero;
  };
  uint64_t flattened = 0;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b) ++j;
    if (j - i == 2) {
      const uint32_t t = sides[i].triangle, u = sides[i + 1].triangle;
      int k = 0;  // u's corner off the edge
      while (before.triangles[3 * u + k] == sides[i].a || before.triangles[3 * u + k] == sides[i].b) ++k;
      if (!coplanar(before, t, u, k) && coplanar(after, t, u, k)) ++flattened;
    }
    i = j;
  }
  return flattened;
}

}  // namespace

Surface snap_coordinates(const Surface& surface, double relative_tolerance, SnapReport& report) {
  if (!(relative_tolerance >= 0) || !std::isfinite(relative_tolerance))
    throw std::invalid_argument("snap_coordinates: the tolerance must be finite and >= 0");
  report = {};
  std::vector<std::vector<Value>> values;
  double diagonal2 = 0;
  for (int axis = 0; axis < 3; ++axis) {
    values.push_back(distinct_values(surface.points, axis));
    if (!values.back().empty()) diagonal2 += std::pow(values.back().back().x - values.back().front().x, 2);
  }
  report.tolerance = relative_tolerance * std::sqrt(diagonal2);

  Soup soup;
  soup.file = surface.file;
  soup.format = surface.format;
  soup.points = surface.points;
  soup.triangles = surface.triangles;
  std::vector<char> moved(surface.num_points(), 0);
  for (int axis = 0; axis < 3 && report.tolerance > 0; ++axis) {
    const std::vector<Value>& v = values[axis];
    const std::vector<double> becomes = snapped_values(v, report.tolerance);
    for (std::size_t i = 0; i < surface.num_points(); ++i) {
      double& x = soup.points[3 * i + axis];
      const auto at = std::lower_bound(v.begin(), v.end(), x, [](const Value& a, double b) { return a.x < b; });
      const double y = becomes[at - v.begin()];
      if (y == x) continue;
      report.largest_move = std::max(report.largest_move, std::abs(y - x));
      ++report.coordinates_moved;
      moved[i] = 1;
      x = y;
    }
  }
  report.points_moved = static_cast<uint64_t>(std::count(moved.begin(), moved.end(), 1));
  Surface snapped = weld(soup);
  snapped.points_in_file = surface.points_in_file;
  report.points_merged = surface.num_points() - snapped.num_points();
  if (report.points_moved > 0) report.edges_flattened = edges_flattened(surface, snapped);
  return snapped;
}

}  // namespace sweepcdt::io
