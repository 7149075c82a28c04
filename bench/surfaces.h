// Closed test surfaces for the benchmarks, generated (no data files): jittered icospheres and tori,
// a sphere with a spherical cavity, and an exactly cospherical sphere (the hull of all integer points
// with x^2 + y^2 + z^2 = n). All outward counterclockwise, notated exterior Negative.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "integer_sphere.h"  // tests/support
#include "sweepcdt/plc.h"

namespace sweepcdt::bench {

struct Mesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<uint32_t, 3>> triangles;
};

// Subdivided icosahedron on the unit sphere: 20 * 4^levels triangles.
inline Mesh icosphere(int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  Mesh m;
  m.points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
    auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      if (const auto it = middle.find(key); it != middle.end()) return it->second;
      m.points.push_back({(m.points[a][0] + m.points[b][0]) / 2, (m.points[a][1] + m.points[b][1]) / 2,
                          (m.points[a][2] + m.points[b][2]) / 2});
      return middle[key] = static_cast<uint32_t>(m.points.size() - 1);
    };
    std::vector<std::array<uint32_t, 3>> finer;
    for (const auto& f : m.triangles) {
      const uint32_t a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
      finer.insert(finer.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
    }
    m.triangles.swap(finer);
  }
  for (auto& p : m.points) {
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (auto& x : p) x /= r;
  }
  return m;
}

// Radial jitter by a relative amount in [-jitter, jitter]: no four points cospherical in practice.
inline void jitter(Mesh& m, double amount, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (auto& p : m.points) {
    const double s = 1 + u(rng);
    for (auto& x : p) x *= s;
  }
}

// Exactly cospherical (tests/support/integer_sphere.h): `level` picks an n whose point count is near
// the icosphere of that level's (level 5: 11136 points, level 6: 41952). Other levels take n from
// the rough count r3(n) ~ 7.5 sqrt(n), moved to the next n that is neither 7 mod 8 (no point) nor a
// multiple of 4 (the points of n/4, doubled): the count there may be off by a factor of 2.
inline Mesh cospherical(int level) {
  int64_t n = level == 5 ? 1850010 : level == 6 ? 30000001 : static_cast<int64_t>(std::pow((10.0 * std::pow(4.0, level) + 2) / 7.5, 2));
  while (n % 8 == 7 || n % 4 == 0) ++n;
  const Plc<3> hull = fixtures::integer_sphere_hull(n);
  Mesh m;
  for (std::size_t i = 0; i < hull.num_points(); ++i) m.points.push_back({hull.points[3 * i], hull.points[3 * i + 1], hull.points[3 * i + 2]});
  for (std::size_t j = 0; j < hull.num_simplices(); ++j) m.triangles.push_back({hull.simplices[3 * j], hull.simplices[3 * j + 1], hull.simplices[3 * j + 2]});
  return m;
}

// A torus with `around` x `across` quads split into triangles (R = 1, r = 0.35).
inline Mesh torus(int around, int across) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const double u = 2 * pi * i / around, v = 2 * pi * j / across;
      m.points.push_back({(1 + 0.35 * std::cos(v)) * std::cos(u), (1 + 0.35 * std::cos(v)) * std::sin(u), 0.35 * std::sin(v)});
    }
  auto id = [&](int i, int j) { return static_cast<uint32_t>((i % around) * across + (j % across)); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  return m;
}

// Appends `inner` (scaled, reversed: a cavity) to `outer`.
inline Mesh with_cavity(Mesh outer, Mesh inner, double scale) {
  const uint32_t base = static_cast<uint32_t>(outer.points.size());
  for (auto p : inner.points) outer.points.push_back({p[0] * scale, p[1] * scale, p[2] * scale});
  for (const auto& t : inner.triangles) outer.triangles.push_back({base + t[0], base + t[2], base + t[1]});
  return outer;
}

inline Plc<3> to_plc(const Mesh& m) {
  Plc<3> plc;
  for (const auto& p : m.points) plc.points.insert(plc.points.end(), p.begin(), p.end());
  for (const auto& t : m.triangles) plc.simplices.insert(plc.simplices.end(), t.begin(), t.end());
  plc.exterior.assign(m.triangles.size(), ExteriorSide::Negative);
  return plc;
}

inline bool write_off(const Mesh& m, const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return false;
  std::fprintf(f, "OFF\n%zu %zu 0\n", m.points.size(), m.triangles.size());
  for (const auto& p : m.points) std::fprintf(f, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
  for (const auto& t : m.triangles) std::fprintf(f, "3 %u %u %u\n", t[0], t[1], t[2]);
  return std::fclose(f) == 0;
}

}  // namespace sweepcdt::bench
