// Test helper: a tetrahedralization that is valid but not the CDT, for the verification tests
// (tests/io/verify_mesh_test.cpp calls the library, tests/cli/check_cli_test.cpp the command line).
#pragma once
#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "sweepcdt/io/volume_mesh.h"
#include "sweepcdt/predicates.h"

namespace sweepcdt::io::testing {

inline predicates::Sign orient(const VolumeMesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  const auto p = [&](uint32_t i) { return m.points.data() + 3 * std::size_t{i}; };
  return predicates::orient<3>({p(a), p(b), p(c), p(d)});
}

// Replaces two tetrahedra abcd, abce whose union is convex by the three around edge de (a 2-3 flip):
// still a valid tetrahedralization of the same domain, but no longer the (unique, perturbed) CDT.
inline bool flip_one_pair(VolumeMesh& m) {
  using predicates::Sign;
  std::map<std::array<uint32_t, 3>, std::pair<std::size_t, uint32_t>> seen;  // facet -> (tet, apex)
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t) {
    const uint32_t* q = m.tetrahedra.data() + 4 * t;
    for (int i = 0; i < 4; ++i) {
      std::array<uint32_t, 3> f{q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]};
      std::sort(f.begin(), f.end());
      const auto [it, fresh] = seen.emplace(f, std::make_pair(t, q[i]));
      if (fresh) continue;
      const uint32_t d = it->second.second, e = q[i];
      const auto [a, b, c] = f;
      const Sign s1 = orient(m, a, b, d, e), s2 = orient(m, b, c, d, e), s3 = orient(m, c, a, d, e);
      if (s1 == Sign::Zero || s1 != s2 || s2 != s3) continue;  // de does not cross abc's interior
      std::vector<uint32_t> tets;
      for (std::size_t u = 0; u < m.num_tetrahedra(); ++u)
        if (u != t && u != it->second.first) tets.insert(tets.end(), m.tetrahedra.begin() + 4 * u, m.tetrahedra.begin() + 4 * u + 4);
      for (const auto& [x, y] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        std::array<uint32_t, 4> n{x, y, d, e};
        if (orient(m, x, y, d, e) == Sign::Negative) std::swap(n[0], n[1]);
        tets.insert(tets.end(), n.begin(), n.end());
      }
      const int32_t region = m.regions.empty() ? 0 : m.regions[t];
      m.tetrahedra = tets;
      if (!m.regions.empty()) m.regions.assign(m.num_tetrahedra(), region);
      return true;
    }
  }
  return false;
}

}  // namespace sweepcdt::io::testing
