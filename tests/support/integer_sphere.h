// The exactly cospherical sphere of the benchmarks and tests: every integer point of the sphere
// x^2 + y^2 + z^2 = n, and the boundary of their convex hull (each point is a hull vertex; hull faces
// through four or more cocircular points, common here, triangulated as the §6 perturbation splits
// them). Integer points are spread evenly over such spheres (for n not of the form 4^a (8b + 7)),
// but their number varies a lot with n (n = 4001: 864 points; 1850010: 11136; 30000001: 41952).
#pragma once
#include <cmath>
#include <cstdint>
#include <utility>

#include "sweepcdt/cdt.h"

namespace sweepcdt::fixtures {

// A facet-bounded PLC: the hull's triangles counterclockwise from outside, exterior Negative.
// Coordinates below 2^13 for n below 2^26, so the integer orientation below is exact in int64.
inline Plc<3> integer_sphere_hull(int64_t n) {
  Plc<3> points;
  const auto r = static_cast<int64_t>(std::sqrt(static_cast<double>(n))) + 1;
  for (int64_t x = -r; x <= r; ++x)
    for (int64_t y = -r; y <= r; ++y) {
      const int64_t rest = n - x * x - y * y;
      if (rest < 0) continue;
      const auto z = static_cast<int64_t>(std::llround(std::sqrt(static_cast<double>(rest))));
      if (z * z != rest) continue;
      points.points.insert(points.points.end(), {double(x), double(y), double(z)});
      if (z != 0) points.points.insert(points.points.end(), {double(x), double(y), double(-z)});
    }
  // The hull: the faces of the Delaunay triangulation with one tetrahedron, turned to face outward.
  const Triangulation<3> dt = cdt(points);
  Plc<3> hull;
  hull.points = points.points;
  const auto q = [&](uint32_t v, int k) { return static_cast<int64_t>(hull.points[3 * std::size_t{v} + k]); };
  for (std::size_t t = 0; t < dt.num_simplices(); ++t)
    for (int i = 0; i < 4; ++i) {
      if (dt.neighbors[4 * t + i] != kNone) continue;
      uint32_t f[3];
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != i) f[j++] = dt.simplices[4 * t + k];
      const uint32_t inside = dt.simplices[4 * t + i];
      int64_t d[3][3];
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k) d[a][k] = q(f[a], k) - q(inside, k);
      const int64_t det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                          d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
      // orient(f, inside) > 0: `inside` below f seen counterclockwise, so f faces outward as it is.
      if (det < 0) std::swap(f[0], f[1]);
      hull.simplices.insert(hull.simplices.end(), {f[0], f[1], f[2]});
      hull.exterior.push_back(ExteriorSide::Negative);
    }
  return hull;
}

}  // namespace sweepcdt::fixtures
