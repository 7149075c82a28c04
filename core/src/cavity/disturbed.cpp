#include "disturbed.h"

#include <algorithm>
#include <array>

#include "../facets.h"
#include "../parallel.h"
#include "../simplex_interior.h"
#include "../simplex_intersection.h"
#include "../tuple_map.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {
namespace {

// Does constraining triangle `tri` disturb tetrahedron `tet` (disturbed.h)? Exact: interior_meets()
// decides whether it meets the open tetrahedron, improper_intersection() whether it meets a facet
// other than in the face their shared vertices span — which covers overlaps and crossings in a
// facet's plane, the cases that leave the interior untouched.
bool disturbs(const Plc<3>& plc, const uint32_t* tet, const uint32_t* tri) {
  const std::array<const double*, 3> t{plc.point(tri[0]), plc.point(tri[1]), plc.point(tri[2])};
  const std::array<uint32_t, 3> t_ids{tri[0], tri[1], tri[2]};
  if (interior_meets<3>({plc.point(tet[0]), plc.point(tet[1]), plc.point(tet[2]), plc.point(tet[3])}, t)) return true;
  for (int i = 0; i < 4; ++i) {
    const FacetKey<3> f = facet_key<3>(tet, i);  // sorted: improper_intersection pairs vertices by id
    if (improper_intersection<3>({plc.point(f[0]), plc.point(f[1]), plc.point(f[2])}, f, t, t_ids)) return true;
  }
  return false;
}

}  // namespace

ConstraintFaces constraint_faces(const Plc<3>& plc, const DelaunayMesh& dt, unsigned threads) {
  const std::size_t m = plc.num_simplices(), tets = dt.tets.size() / 4;
  TupleMap<3> constraint_of(m);
  for (uint32_t c = 0; c < m; ++c) {
    FacetKey<3> key;
    std::copy_n(plc.simplex(c), 3, key.begin());
    std::sort(key.begin(), key.end());
    constraint_of.emplace(key, c);
  }
  ConstraintFaces result;
  result.of_facet.assign(4 * tets, kNone);
  // Each facet is looked up once, from the lower-numbered of its two tetrahedra, which writes both
  // sides: so each entry has one writer, and the parts run on their own (a random access into the
  // map per lookup: 0.77 s at 1.3M triangles on one thread, looking up every facet twice).
  for_each_part(tets, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      for (int i = 0; i < 4; ++i) {
        const uint32_t across = dt.neighbors[4 * t + i];
        if (across != kNone && across / 4 < t) continue;
        const uint32_t c = constraint_of.find(facet_key<3>(&dt.tets[4 * t], i));
        if (c == TupleMap<3>::kAbsent) continue;
        result.of_facet[4 * t + i] = c;
        if (across != kNone) result.of_facet[across] = c;
      }
  });
  std::vector<uint8_t> present(m, 0);
  for (const uint32_t c : result.of_facet)
    if (c != kNone) present[c] = 1;
  for (uint32_t c = 0; c < m; ++c)
    if (!present[c]) result.missing.push_back(c);
  return result;
}

Disturbed disturbed_tetrahedra(const Plc<3>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& missing) {
  const std::size_t tets = dt.tets.size() / 4;
  Disturbed result;
  result.tets.assign(tets, 0);
  if (missing.empty()) return result;
  std::vector<uint8_t>& disturbed = result.tets;
  std::vector<uint32_t> tet_at(plc.num_points(), kNone), degree(plc.num_points(), 0);
  for (uint32_t t = 0; t < tets; ++t)
    for (int i = 0; i < 4; ++i) tet_at[dt.tets[4 * t + i]] = t, ++degree[dt.tets[4 * t + i]];
  std::vector<uint32_t> visited(tets, 0), star, queue;
  uint32_t stamp = 0;
  const auto visit = [&](uint32_t t) {
    if (visited[t] == stamp) return false;
    visited[t] = stamp;
    return true;
  };
  for (const uint32_t c : missing) {
    ++stamp;
    const uint32_t* tri = plc.simplex(c);
    // The tetrahedra around the constraint's vertex a with the fewest: a walk across the facets
    // through a. (Each is tested; an input vertex at the apex of a fan across a flat face can have
    // hundreds, and a Steiner point on its edge a few dozen.)
    const uint32_t a = *std::min_element(tri, tri + 3, [&](uint32_t x, uint32_t y) { return degree[x] < degree[y]; });
    queue.clear();
    star.assign(1, tet_at[a]);
    visit(star[0]);
    for (std::size_t head = 0; head < star.size(); ++head) {
      const uint32_t t = star[head];
      for (int i = 0; i < 4; ++i) {
        const uint32_t nb = dt.neighbors[4 * t + i];
        if (dt.tets[4 * t + i] != a && nb != kNone && visit(nb / 4)) star.push_back(nb / 4);
      }
      if (disturbs(plc, &dt.tets[4 * t], tri)) queue.push_back(t);
    }
    if (queue.empty()) return {};  // impossible for a missing constraint: fall back
    result.first.push_back(queue.front());
    // Then outward through neighbours from every disturbed tetrahedron.
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const uint32_t t = queue[head];
      disturbed[t] = 1;
      for (int i = 0; i < 4; ++i) {
        const uint32_t nb = dt.neighbors[4 * t + i];
        if (nb != kNone && visit(nb / 4) && disturbs(plc, &dt.tets[nb / 4 * 4], tri)) queue.push_back(nb / 4);
      }
    }
  }
  return result;
}

}  // namespace sweepcdt::detail
