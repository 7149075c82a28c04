#include "disturbed.h"

#include <algorithm>
#include <array>
#include <atomic>

#include "../facets.h"
#include "../parallel.h"
#include "../simplex_interior.h"
#include "../simplex_intersection.h"
#include "../tuple_map.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {
namespace {

// Whether every vertex of simplex s that constraining simplex c does not share lies strictly on one
// side of c's hyperplane (exact orientations; none of the 35 planes of interior_meets, nor the facet
// tests). Then s meets that hyperplane only in the hull of the shared vertices, a face of both, so
// neither its interior nor a facet meets c anywhere else: c does not disturb s. On thingi_1706459.stl
// 40% of the simplices tested lie so (the hyperplane passes through the constraint's vertex the
// search starts around, and beside the disturbed simplices), and 37% more have c outside a facet
// (disturbs: one facet tested, not four).
template <int D>
bool strictly_beside(const uint32_t* s, const std::array<const double*, D + 1>& s_points, const std::array<uint32_t, D>& c_ids,
                     const std::array<const double*, D>& c_points) {
  predicates::Coords<D + 1> plane;
  std::copy(c_points.begin(), c_points.end(), plane.begin());
  predicates::Sign side = predicates::Sign::Zero;
  for (int k = 0; k <= D; ++k) {
    if (std::find(c_ids.begin(), c_ids.end(), s[k]) != c_ids.end()) continue;  // shared: in the hyperplane
    plane[D] = s_points[k];
    const predicates::Sign sk = predicates::orient<D>(plane);
    if (sk == predicates::Sign::Zero || (side != predicates::Sign::Zero && sk != side)) return false;
    side = sk;
  }
  return true;
}

// Does constraining simplex `c` disturb simplex `s` (disturbed.h)? Exact: interior_meets() decides
// whether it meets the open simplex, improper_intersection() whether it meets a facet other than in
// the face their shared vertices span — which covers overlaps and crossings in a facet's hyperplane,
// the cases that leave the interior untouched.
template <int D>
bool disturbs(const Plc<D>& plc, const uint32_t* s, const uint32_t* c) {
  std::array<const double*, D> c_points;
  std::array<uint32_t, D> c_ids;
  for (int k = 0; k < D; ++k) c_points[k] = plc.point(c[k]), c_ids[k] = c[k];
  std::array<const double*, D + 1> s_points;
  for (int k = 0; k <= D; ++k) s_points[k] = plc.point(s[k]);
  if (strictly_beside<D>(s, s_points, c_ids, c_points)) return false;
  // When c lies on the closed outer side of a facet's hyperplane, it meets s only in that facet, and
  // another facet meets it improperly only at points of that one, where that one does too (the
  // faces two facets share span their common vertices): that facet alone is tested.
  int outer = -1;
  if (interior_meets<D>(s_points, c_points, &outer)) return true;
  for (int i = 0; i <= D; ++i) {
    if (outer >= 0 && i != outer) continue;
    const FacetKey<D> f = facet_key<D>(s, i);  // sorted: improper_intersection pairs vertices by id
    std::array<const double*, D> f_points;
    for (int k = 0; k < D; ++k) f_points[k] = plc.point(f[k]);
    if (improper_intersection<D>(f_points, f, c_points, c_ids)) return true;
  }
  return false;
}

// Whether constraining triangle c meets facet i of tetrahedron s (opposite its vertex i) other than
// in a face of both (improper_intersection); the facet's vertices sorted, as there.
bool meets_facet_improperly(const Plc<3>& plc, const uint32_t* s, int i, const uint32_t* c) {
  const FacetKey<3> f = facet_key<3>(s, i);
  return improper_intersection<3>({plc.point(f[0]), plc.point(f[1]), plc.point(f[2])}, f,
                                  {plc.point(c[0]), plc.point(c[1]), plc.point(c[2])}, {c[0], c[1], c[2]});
}

}  // namespace

template <int D>
ConstraintFaces constraint_faces(const Plc<D>& plc, const DelaunayMesh& dt, unsigned threads) {
  constexpr int kVertices = D + 1;
  const std::size_t m = plc.num_simplices(), simplices = dt.tets.size() / kVertices;
  TupleMap<D> constraint_of(m);
  for (uint32_t c = 0; c < m; ++c) {
    FacetKey<D> key;
    std::copy_n(plc.simplex(c), D, key.begin());
    std::sort(key.begin(), key.end());
    constraint_of.emplace(key, c);
  }
  ConstraintFaces result;
  result.of_facet.assign(kVertices * simplices, kNone);
  // Each facet is looked up once, from the lower-numbered of its two simplices, which writes both
  // sides: so each entry has one writer, and the parts run on their own (a random access into the
  // map per lookup: 0.77 s at 1.3M triangles on one thread, looking up every facet twice).
  for_each_part(simplices, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      for (int i = 0; i < kVertices; ++i) {
        const uint32_t across = dt.neighbors[kVertices * t + i];
        if (across != kNone && across / kVertices < t) continue;
        const uint32_t c = constraint_of.find(facet_key<D>(&dt.tets[kVertices * t], i));
        if (c == TupleMap<D>::kAbsent) continue;
        result.of_facet[kVertices * t + i] = c;
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

template <int D>
Disturbed disturbed_simplices(const Plc<D>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& missing, unsigned threads) {
  constexpr int kVertices = D + 1;
  const std::size_t simplices = dt.tets.size() / kVertices;
  Disturbed result;
  result.tets.assign(simplices, 0);
  if (missing.empty()) return result;
  std::vector<uint8_t>& disturbed = result.tets;
  std::vector<uint32_t> simplex_at(plc.num_points(), kNone), degree(plc.num_points(), 0);
  for (uint32_t t = 0; t < simplices; ++t)
    for (int i = 0; i < kVertices; ++i) simplex_at[dt.tets[kVertices * t + i]] = t, ++degree[dt.tets[kVertices * t + i]];
  result.first.assign(missing.size(), kNone);
  std::atomic<bool> none_found{false};
  // Each part writes its constraints' `first` entries and sets flags (a union: the order of the
  // writes does not matter; atomic, as two parts may set one flag).
  for_each_part(missing.size(), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    std::vector<uint32_t> visited(simplices, 0), star, queue;
    uint32_t stamp = 0;
    const auto visit = [&](uint32_t t) {
      if (visited[t] == stamp) return false;
      visited[t] = stamp;
      return true;
    };
    for (std::size_t k = begin; k < end; ++k) {
      ++stamp;
      const uint32_t* constraint = plc.simplex(missing[k]);
      // The simplices around the constraint's vertex a with the fewest: a walk across the facets
      // through a (no exact test; an input vertex at the apex of a fan across a flat face can have
      // hundreds, and a Steiner point on its edge a few dozen).
      const uint32_t a =
          *std::min_element(constraint, constraint + D, [&](uint32_t x, uint32_t y) { return degree[x] < degree[y]; });
      queue.clear();
      star.assign(1, simplex_at[a]);
      visit(star[0]);
      for (std::size_t head = 0; head < star.size(); ++head) {
        const uint32_t t = star[head];
        for (int i = 0; i < kVertices; ++i) {
          const uint32_t nb = dt.neighbors[kVertices * t + i];
          if (dt.tets[kVertices * t + i] != a && nb != kNone && visit(nb / kVertices)) star.push_back(nb / kVertices);
        }
      }
      // One disturbed simplex is enough to start from: the disturbed simplices are connected across
      // facets (disturbed.h). Those that hold a whole edge of the constraint through a are tested first:
      // when that edge is a Delaunay edge, the constraint's points next to it lie in one of them, or
      // in a facet of one (overlapped improperly, as the constraint is no Delaunay face), so one of
      // them is disturbed: a ring of about five simplices, where the star holds a few dozen (the
      // exact tests are most of the search). The rest of the star is tested after them.
      const auto holds_edge_of_constraint = [&](uint32_t t) {
        for (int i = 0; i < kVertices; ++i) {
          const uint32_t v = dt.tets[kVertices * t + i];
          if (v != a && std::find(constraint, constraint + D, v) != constraint + D) return true;
        }
        return false;
      };
      std::stable_partition(star.begin(), star.end(), holds_edge_of_constraint);
      for (const uint32_t t : star)
        if (disturbs<D>(plc, &dt.tets[kVertices * t], constraint)) {
          queue.push_back(t);
          break;
        }
      if (queue.empty()) {  // impossible for a missing constraint: fall back
        none_found = true;
        return;
      }
      ++stamp;  // the star was only walked: the search tests its simplices as it reaches them
      visit(queue.front());
      result.first[k] = queue.front();
      // Then outward through neighbours from every disturbed simplex. In 3D only across the facets
      // the constraint meets improperly (other than in a face of both): the simplex on the other
      // side of such a facet is disturbed (it meets the constraint there), and every disturbed
      // simplex is reached that way — the constraint's pieces in two simplices meet in their common
      // facet, or along a Delaunay edge through the constraint's relative interior, around which
      // every facet meets the constraint improperly; and where the constraint overlaps a facet or
      // runs along one with its edge, that facet meets it improperly too. A facet test is a few
      // orientations where `disturbs` ran the separating planes on every neighbour (the whole search
      // 0.35x of its time on a marching-tetrahedra scan, 0.6x on thingi). In higher dimensions a
      // facet test is a linear program: the neighbours are tested instead.
      for (std::size_t head = 0; head < queue.size(); ++head) {
        const uint32_t t = queue[head];
        std::atomic_ref<uint8_t>(disturbed[t]).store(1, std::memory_order_relaxed);
        for (int i = 0; i < kVertices; ++i) {
          const uint32_t nb = dt.neighbors[kVertices * t + i];
          if (nb == kNone || visited[nb / kVertices] == stamp) continue;
          if constexpr (D == 3) {
            if (!meets_facet_improperly(plc, &dt.tets[kVertices * t], i, constraint)) continue;
            visit(nb / kVertices);
            queue.push_back(nb / kVertices);
          } else if (visit(nb / kVertices) && disturbs<D>(plc, &dt.tets[nb / kVertices * kVertices], constraint)) {
            queue.push_back(nb / kVertices);
          }
        }
      }
    }
  }, kConstraintsPerThread);
  if (none_found) return {};
  return result;
}

#define SWEEPCDT_DISTURBED(D)                                                                                  \
  template ConstraintFaces constraint_faces<D>(const Plc<D>&, const DelaunayMesh&, unsigned);                   \
  template Disturbed disturbed_simplices<D>(const Plc<D>&, const DelaunayMesh&, const std::vector<uint32_t>&, unsigned);
SWEEPCDT_DISTURBED(2)
SWEEPCDT_DISTURBED(3)
SWEEPCDT_DISTURBED(4)
SWEEPCDT_DISTURBED(5)
#undef SWEEPCDT_DISTURBED

}  // namespace sweepcdt::detail
