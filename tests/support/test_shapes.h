// Small PLCs used across the tests, built by hand with exactly representable coordinates.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sweepcdt/plc.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::fixtures {

// The unit cube's surface: point i = (i&1, (i>>1)&1, (i>>2)&1), 12 triangles counterclockwise seen
// from outside, so the inside is the positive side and every triangle is notated exterior Negative.
inline Plc<3> unit_cube_surface(double scale = 1.0) {
  Plc<3> plc;
  for (int i = 0; i < 8; ++i)
    plc.points.insert(plc.points.end(), {scale * (i & 1), scale * ((i >> 1) & 1), scale * ((i >> 2) & 1)});
  plc.simplices = {0, 2, 3, 0, 3, 1,   4, 5, 7, 4, 7, 6,   0, 1, 5, 0, 5, 4,
                   2, 6, 7, 2, 7, 3,   0, 4, 6, 0, 6, 2,   1, 3, 7, 1, 7, 5};
  plc.exterior.assign(12, ExteriorSide::Negative);
  return plc;
}

// The surface of the box [0,k]^3 with every face cut into k x k unit squares of two triangles:
// 12 k^2 triangles, many exactly coplanar neighbours. Outward counterclockwise.
inline Plc<3> grid_box_surface(int k) {
  Plc<3> plc;
  auto vertex = [&](int x, int y, int z) {
    plc.points.insert(plc.points.end(), {double(x), double(y), double(z)});
    return static_cast<uint32_t>(plc.points.size() / 3 - 1);
  };
  // Vertices are created per face; shared edge vertices would be duplicates, so index them by position.
  std::vector<int64_t> index((k + 1) * (k + 1) * (k + 1), -1);
  auto id = [&](int x, int y, int z) {
    int64_t& slot = index[(x * (k + 1) + y) * (k + 1) + z];
    if (slot < 0) slot = vertex(x, y, z);
    return static_cast<uint32_t>(slot);
  };
  // For each axis and each side, the face's (u, v) directions are chosen so (u x v) points outward.
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int a = 0; a < k; ++a)
        for (int b = 0; b < k; ++b) {
          auto at = [&](int da, int db) {
            int c[3];
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            c[axis] = side * k;
            c[u] = a + da;
            c[v] = b + db;
            return id(c[0], c[1], c[2]);
          };
          const uint32_t p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          if (side == 1) plc.simplices.insert(plc.simplices.end(), {p00, p10, p11, p00, p11, p01});
          else plc.simplices.insert(plc.simplices.end(), {p00, p11, p10, p00, p01, p11});
        }
  plc.exterior.assign(plc.num_simplices(), ExteriorSide::Negative);
  return plc;
}

}  // namespace sweepcdt::fixtures

namespace sweepcdt::fixtures {

// Appends a box surface [lo, hi]^3 (two triangles per face), its triangles counterclockwise seen
// from outside when `outward`, else reversed; notated so that the box's inside (outward) or outside
// (reversed: a cavity) is the domain.
inline void add_box(Plc<3>& plc, const std::array<double, 3>& lo, const std::array<double, 3>& hi, bool outward) {
  const uint32_t base = static_cast<uint32_t>(plc.num_points());
  for (int i = 0; i < 8; ++i)
    plc.points.insert(plc.points.end(), {(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]});
  const uint32_t faces[36] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                              2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  for (int t = 0; t < 12; ++t) {
    uint32_t a = base + faces[3 * t], b = base + faces[3 * t + 1], c = base + faces[3 * t + 2];
    if (!outward) std::swap(b, c);
    plc.simplices.insert(plc.simplices.end(), {a, b, c});
    plc.exterior.push_back(ExteriorSide::Negative);  // counterclockwise from the exterior side
  }
}

// A triangular prism with its top rotated by `twist` radians about the axis (Schönhardt's polyhedron
// for twist in (0, pi/3) with the quads split the "wrong" way): 6 points, 8 triangles, outward.
inline Plc<3> twisted_prism(double twist) {
  Plc<3> plc;
  const double pi = 3.14159265358979323846;
  for (int level = 0; level < 2; ++level)
    for (int i = 0; i < 3; ++i) {
      const double angle = 2 * pi * i / 3 + (level ? twist : 0.0);
      plc.points.insert(plc.points.end(), {std::cos(angle), std::sin(angle), double(level)});
    }
  // bottom (0,1,2) seen from below counterclockwise, top (3,4,5); side quads i, i+1 split by the
  // diagonal from bottom i to top i+1.
  plc.simplices = {0, 2, 1, 3, 4, 5};
  for (uint32_t i = 0; i < 3; ++i) {
    const uint32_t j = (i + 1) % 3;
    plc.simplices.insert(plc.simplices.end(), {i, j, 3 + j, i, 3 + j, 3 + i});
  }
  plc.exterior.assign(8, ExteriorSide::Negative);
  return plc;
}

// Appends tetrahedron `ids` (points already in plc) as four faces notated so that the domain is on
// the tetrahedron's side of each.
inline void add_tetrahedron(Plc<3>& plc, std::array<uint32_t, 4> ids) {
  for (int i = 0; i < 4; ++i) {
    std::array<uint32_t, 3> f;
    for (int k = 0, j = 0; k < 4; ++k)
      if (k != i) f[j++] = ids[k];
    plc.simplices.insert(plc.simplices.end(), f.begin(), f.end());
    const auto side = predicates::orient<3>({plc.point(f[0]), plc.point(f[1]), plc.point(f[2]), plc.point(ids[i])});
    plc.exterior.push_back(side == predicates::Sign::Positive ? ExteriorSide::Negative : ExteriorSide::Positive);
  }
}

}  // namespace sweepcdt::fixtures
