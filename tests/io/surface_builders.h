// Small hand-made soups for the io tests: axis-aligned cubes (optionally inside out), tetrahedra.
#pragma once
#include <array>
#include <cmath>
#include <vector>
#include <string>

#include "sweepcdt/io/soup.h"

namespace sweepcdt::io::testing {

// Appends the box [lo, hi] (the cube [lo, hi]^3) as 8 points and 12 triangles, counterclockwise seen from outside
// (outward) or the reverse. Quads are split along the diagonal from corner a to corner c, so on the
// face x = hi the diagonal runs through the points with y = z (a degenerate case for ray tests).
inline void add_box(Soup& soup, std::array<double, 3> lo, std::array<double, 3> hi, bool outward = true) {
  const auto base = static_cast<uint32_t>(soup.num_points());
  for (uint32_t i = 0; i < 8; ++i) soup.points.insert(soup.points.end(), {i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]});
  constexpr std::array<std::array<uint32_t, 4>, 6> quads{{{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}};
  for (const auto& q : quads) {
    for (const auto& t : {std::array<uint32_t, 3>{q[0], q[1], q[2]}, std::array<uint32_t, 3>{q[0], q[2], q[3]}}) {
      if (outward) soup.triangles.insert(soup.triangles.end(), {base + t[0], base + t[1], base + t[2]});
      else soup.triangles.insert(soup.triangles.end(), {base + t[0], base + t[2], base + t[1]});
    }
  }
}

inline void add_cube(Soup& soup, double lo, double hi, bool outward = true) { add_box(soup, {lo, lo, lo}, {hi, hi, hi}, outward); }

inline Soup cube_soup(double lo = 0, double hi = 1, bool outward = true) {
  Soup soup;
  soup.file = "cube";
  add_cube(soup, lo, hi, outward);
  return soup;
}

// Tetrahedron with corner at (x, y, z), edge length 1, outward.
inline void add_tetrahedron(Soup& soup, double x, double y, double z) {
  const auto base = static_cast<uint32_t>(soup.num_points());
  soup.points.insert(soup.points.end(), {x, y, z, x + 1, y, z, x, y + 1, z, x, y, z + 1});
  for (const auto& t : {std::array<uint32_t, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}})
    soup.triangles.insert(soup.triangles.end(), {base + t[0], base + t[1], base + t[2]});
}

// A regular icosahedron (circumradius 1.902 * scale) around the origin, outward unless `outward` is
// false. Its faces are the vertex triples at mutual distance 2 * scale.
inline void add_icosahedron(Soup& soup, double scale, bool outward = true) {
  const auto base = static_cast<uint32_t>(soup.num_points());
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> v;
  for (double a : {-1.0, 1.0})
    for (double b : {-phi, phi}) v.insert(v.end(), {{0, a, b}, {a, b, 0}, {b, 0, a}});
  for (auto& p : v)
    for (double& x : p) x *= scale;
  auto d2 = [&](uint32_t i, uint32_t j) {
    double s = 0;
    for (int k = 0; k < 3; ++k) s += (v[i][k] - v[j][k]) * (v[i][k] - v[j][k]);
    return s;
  };
  auto edge = [&](uint32_t i, uint32_t j) { return std::abs(d2(i, j) - 4 * scale * scale) < 1e-9 * scale * scale; };
  for (const auto& p : v) soup.points.insert(soup.points.end(), p.begin(), p.end());
  for (uint32_t i = 0; i < 12; ++i)
    for (uint32_t j = i + 1; j < 12; ++j)
      for (uint32_t k = j + 1; k < 12; ++k) {
        if (!edge(i, j) || !edge(j, k) || !edge(i, k)) continue;
        // Outward iff the normal (b - a) x (c - a) points away from the origin.
        const auto &a = v[i], &b = v[j], &c = v[k];
        const double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                             (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                             (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
        const bool out = n[0] * a[0] + n[1] * a[1] + n[2] * a[2] > 0;
        if (out == outward) soup.triangles.insert(soup.triangles.end(), {base + i, base + j, base + k});
        else soup.triangles.insert(soup.triangles.end(), {base + i, base + k, base + j});
      }
}

}  // namespace sweepcdt::io::testing
