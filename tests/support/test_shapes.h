// Small PLCs used across the tests, built by hand: most with exactly representable coordinates, the
// surfaces of revolution (add_revolved) with rounded sines and cosines.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
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

// The right prism of twisted_prism(0) (six exactly cospherical points: both triangles have one
// circumcircle, mirrored at z = 1/2) with its side quads split as a staircase: the last quad by the
// diagonal from bottom 0 to top 5 instead of 2 to 3, so bottom 0 meets two diagonals and no cycle
// is left — three tetrahedra fill it. Outward, exterior Negative.
inline Plc<3> staircase_prism() {
  Plc<3> plc = twisted_prism(0.0);
  // The last quad (2, 0, 3, 5): triangles (2, 0, 3) and (2, 3, 5) become (2, 0, 5) and (0, 3, 5).
  std::copy_n(std::array<uint32_t, 6>{2, 0, 5, 0, 3, 5}.begin(), 6, plc.simplices.end() - 6);
  return plc;
}

// The boundary of the Kuhn triangulation of the unit D-cube (the D! simplices along the diagonal
// from the origin to (1, ..., 1)), with point ids scrambled: the point with coordinate bits b
// (bit k = coordinate k) gets id b ^ scramble. All 2^D points are cospherical, so every simplex of
// a triangulation is constrained Delaunay before the perturbation (paper §6) decides; every Kuhn
// simplex holds both ends of the diagonal, so an order that pulls any other vertex first cannot
// give it — the vertex-id order when scramble is not 0 or 2^D - 1. Exterior notations put the
// cube's inside in the domain.
template <int D>
Plc<D> kuhn_cube_surface(uint32_t scramble) {
  Plc<D> plc;
  const uint32_t n = 1u << D;
  plc.points.resize(std::size_t{n} * D);
  for (uint32_t b = 0; b < n; ++b)
    for (int k = 0; k < D; ++k) plc.points[std::size_t{b ^ scramble} * D + k] = (b >> k) & 1;
  // Each facet (sorted ids) of the Kuhn simplices, how many simplices hold it, and an apex.
  std::map<std::array<uint32_t, D>, std::pair<int, uint32_t>> facets;
  std::array<int, D> axes;
  for (int k = 0; k < D; ++k) axes[k] = k;
  do {
    std::array<uint32_t, D + 1> s;
    uint32_t b = 0;
    s[0] = scramble;
    for (int k = 0; k < D; ++k) s[k + 1] = (b |= 1u << axes[k]) ^ scramble;
    for (int i = 0; i <= D; ++i) {
      std::array<uint32_t, D> f;
      for (int k = 0, j = 0; k <= D; ++k)
        if (k != i) f[j++] = s[k];
      std::sort(f.begin(), f.end());
      auto& [count, apex] = facets[f];
      ++count;
      apex = s[i];
    }
  } while (std::next_permutation(axes.begin(), axes.end()));
  for (const auto& [f, entry] : facets) {
    if (entry.first != 1) continue;  // interior facet
    predicates::Coords<D + 1> c;
    for (int k = 0; k < D; ++k) c[k] = plc.point(f[k]);
    c[D] = plc.point(entry.second);
    plc.simplices.insert(plc.simplices.end(), f.begin(), f.end());
    plc.exterior.push_back(predicates::orient<D>(c) == predicates::Sign::Positive ? ExteriorSide::Negative : ExteriorSide::Positive);
  }
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

// Appends the surface of revolution about the z axis of a profile, as CAD systems tessellate one:
// each (radius > 0, z) of `profile`, bottom to top, a ring of `around` points; quads between rings
// split by a diagonal; fans to the axis at z_bottom and z_top. Counterclockwise seen from outside
// (around, then up), exterior Negative; `outward` false reverses it (a cavity: the domain outside).
inline void add_revolved(Plc<3>& plc, const std::vector<std::array<double, 2>>& profile, int around, double z_bottom, double z_top,
                         bool outward = true) {
  constexpr double pi = std::numbers::pi;
  const auto add = [&](double x, double y, double z) {
    plc.points.insert(plc.points.end(), {x, y, z});
    return static_cast<uint32_t>(plc.num_points() - 1);
  };
  std::vector<std::vector<uint32_t>> ring(profile.size());
  for (std::size_t k = 0; k < profile.size(); ++k) {
    const auto [r, z] = profile[k];
    for (int j = 0; j < around; ++j) ring[k].push_back(add(r * std::cos(2 * pi * j / around), r * std::sin(2 * pi * j / around), z));
  }
  const uint32_t bottom = add(0, 0, z_bottom), top = add(0, 0, z_top);
  const auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    if (!outward) std::swap(b, c);
    plc.simplices.insert(plc.simplices.end(), {a, b, c});
    plc.exterior.push_back(ExteriorSide::Negative);
  };
  for (int j = 0; j < around; ++j) {
    const int next = (j + 1) % around;
    for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
      triangle(ring[k][j], ring[k][next], ring[k + 1][next]);
      triangle(ring[k][j], ring[k + 1][next], ring[k + 1][j]);
    }
    triangle(bottom, ring[0][next], ring[0][j]);
    triangle(top, ring.back()[j], ring.back()[next]);
  }
}

// A latitude-longitude sphere of `rings` bands about the origin (add_revolved).
inline void add_uv_sphere(Plc<3>& plc, double radius, int rings, int around, bool outward) {
  constexpr double pi = std::numbers::pi;
  std::vector<std::array<double, 2>> profile;
  for (int i = rings - 1; i >= 1; --i) profile.push_back({radius * std::sin(pi * i / rings), radius * std::cos(pi * i / rings)});
  add_revolved(plc, profile, around, -radius, radius, outward);
}

}  // namespace sweepcdt::fixtures

namespace sweepcdt::fixtures {

// The closed surface of a profile extruded along z from 0 to `depth`. The profile is the union of the
// columns [xs[j], xs[j+1]] x [0, tops[j]] (xs increasing, tops > 0). Caps are triangulated column by
// column as strips between the two vertical chains of vertices; side walls are two triangles per
// outline edge. Outward counterclockwise, exterior Negative. Makes combs, slabs and steps.
inline Plc<3> extruded_columns(const std::vector<double>& xs, const std::vector<double>& tops, double depth) {
  Plc<3> plc;
  const std::size_t n = tops.size();
  // Vertical chain of profile vertices at xs[j]: heights 0 and the tops of the columns beside it.
  std::vector<std::vector<double>> chain(n + 1);
  for (std::size_t j = 0; j <= n; ++j) {
    chain[j].push_back(0.0);
    if (j > 0) chain[j].push_back(tops[j - 1]);
    if (j < n) chain[j].push_back(tops[j]);
    std::sort(chain[j].begin(), chain[j].end());
    chain[j].erase(std::unique(chain[j].begin(), chain[j].end()), chain[j].end());
  }
  // Point ids: index of (j, k) in profile order; layer 0 (z = 0) then layer 1 (z = depth).
  std::vector<std::vector<uint32_t>> id(n + 1);
  uint32_t count = 0;
  for (std::size_t j = 0; j <= n; ++j)
    for (std::size_t k = 0; k < chain[j].size(); ++k) id[j].push_back(count++);
  for (int layer = 0; layer < 2; ++layer)
    for (std::size_t j = 0; j <= n; ++j)
      for (double y : chain[j]) plc.points.insert(plc.points.end(), {xs[j], y, layer ? depth : 0.0});
  auto tri = [&](uint32_t a, uint32_t b, uint32_t c) { plc.simplices.insert(plc.simplices.end(), {a, b, c}); };
  // Caps: column j spans chain j up to tops[j] on the left and chain j+1 up to tops[j] on the right.
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<uint32_t> left, right;  // bottom to top
    for (std::size_t k = 0; k < chain[j].size() && chain[j][k] <= tops[j]; ++k) left.push_back(id[j][k]);
    for (std::size_t k = 0; k < chain[j + 1].size() && chain[j + 1][k] <= tops[j]; ++k) right.push_back(id[j + 1][k]);
    auto height = [&](uint32_t v) { return plc.points[3 * v + 1]; };
    std::size_t l = 0, r = 0;
    while (l + 1 < left.size() || r + 1 < right.size()) {
      const bool up_left = r + 1 == right.size() || (l + 1 < left.size() && height(left[l + 1]) <= height(right[r + 1]));
      // Counterclockwise in xy (top cap, z = depth), reversed for the bottom cap.
      const uint32_t a = left[l], b = right[r], c = up_left ? left[l + 1] : right[r + 1];
      tri(count + a, count + b, count + c);
      tri(a, c, b);
      if (up_left) ++l;
      else ++r;
    }
  }
  // Outline, counterclockwise: along the bottom, then leftwards over the tops; at each xs[j] it
  // arrives at the top of column j and leaves at the top of column j-1 (no vertex lies between).
  std::vector<uint32_t> outline;
  for (std::size_t j = 0; j <= n; ++j) outline.push_back(id[j][0]);
  auto at_height = [&](std::size_t j, double y) {
    return id[j][std::lower_bound(chain[j].begin(), chain[j].end(), y) - chain[j].begin()];
  };
  for (std::size_t j = n + 1; j-- > 0;) {
    if (j < n && outline.back() != at_height(j, tops[j])) outline.push_back(at_height(j, tops[j]));
    if (j > 0 && outline.back() != at_height(j, tops[j - 1])) outline.push_back(at_height(j, tops[j - 1]));
  }
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const uint32_t p = outline[i], q = outline[(i + 1) % outline.size()];
    if (p == q) continue;
    tri(p, q, count + q);
    tri(p, count + q, count + p);
  }
  plc.exterior.assign(plc.num_simplices(), ExteriorSide::Negative);
  return plc;
}

// A triangular prism over the triangle (0,0), (1,0), (1,h) from z = 0 to 1, its side quads split
// without a cycle: the dihedral angle at the edge through the origin is atan(h).
inline Plc<3> wedge(double h) {
  Plc<3> plc;
  plc.points = {0, 0, 0, 1, 0, 0, 1, h, 0, 0, 0, 1, 1, 0, 1, 1, h, 1};
  plc.simplices = {0, 2, 1, 3, 4, 5,         // bottom, top
                   0, 1, 4, 0, 4, 3,         // y = 0 side
                   1, 2, 5, 1, 5, 4,         // x = 1 side
                   0, 3, 5, 0, 5, 2};        // slanted side
  plc.exterior.assign(8, ExteriorSide::Negative);
  return plc;
}

// A cone with a sharp apex: a regular k-gon of radius r at z = 0 and the apex (0, 0, 1); the base is
// fanned from its first vertex. Small angles between the segments at the apex.
inline Plc<3> needle(int k, double r) {
  Plc<3> plc;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < k; ++i) plc.points.insert(plc.points.end(), {r * std::cos(2 * pi * i / k), r * std::sin(2 * pi * i / k), 0.0});
  plc.points.insert(plc.points.end(), {0.0, 0.0, 1.0});
  const uint32_t apex = static_cast<uint32_t>(k);
  for (uint32_t i = 0; i < apex; ++i) plc.simplices.insert(plc.simplices.end(), {i, (i + 1) % apex, apex});
  for (uint32_t i = 1; i + 1 < apex; ++i) plc.simplices.insert(plc.simplices.end(), {0, i + 1, i});
  plc.exterior.assign(plc.num_simplices(), ExteriorSide::Negative);
  return plc;
}

}  // namespace sweepcdt::fixtures
