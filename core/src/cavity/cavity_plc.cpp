#include "cavity_plc.h"

#include <algorithm>
#include <array>

#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {
namespace {

// One constraint of a cavity PLC, in the whole PLC's ids.
struct Piece {
  uint32_t cavity;
  std::array<uint32_t, 3> v;
  ExteriorSide exterior;
};

// The Cavity tetrahedra's components across their facets, numbered 0.. (kNone for other places).
std::vector<uint32_t> cavity_of(const DelaunayMesh& dt, const std::vector<Place>& place, uint32_t& count) {
  std::vector<uint32_t> cavity(place.size(), kNone), queue;
  count = 0;
  for (uint32_t start = 0; start < place.size(); ++start) {
    if (place[start] != Place::Cavity || cavity[start] != kNone) continue;
    cavity[start] = count;
    queue.assign(1, start);
    while (!queue.empty()) {
      const uint32_t t = queue.back();
      queue.pop_back();
      for (int i = 0; i < 4; ++i) {
        const uint32_t nb = dt.neighbors[4 * t + i];
        if (nb == kNone || place[nb / 4] != Place::Cavity || cavity[nb / 4] != kNone) continue;
        cavity[nb / 4] = count;
        queue.push_back(nb / 4);
      }
    }
    ++count;
  }
  return cavity;
}

// Facet i of tetrahedron `tet`, notated with the tetrahedron's side exterior.
Piece facet_with_exterior_side(const Plc<3>& plc, uint32_t cavity, const uint32_t* tet, int i) {
  std::array<uint32_t, 3> f;
  for (int k = 0, r = 0; k < 4; ++k)
    if (k != i) f[r++] = tet[k];
  const auto s = predicates::orient<3>({plc.point(f[0]), plc.point(f[1]), plc.point(f[2]), plc.point(tet[i])});
  return {cavity, f, s == predicates::Sign::Positive ? ExteriorSide::Positive : ExteriorSide::Negative};
}

}  // namespace

Cavities cavity_plcs(const Plc<3>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& constraint_of_facet,
                     const std::vector<uint32_t>& missing, const std::vector<uint32_t>& first_disturbed,
                     const std::vector<Place>& place) {
  const std::size_t tets = dt.tets.size() / 4;
  Cavities result;
  uint32_t count = 0;
  const std::vector<uint32_t> cavity = cavity_of(dt, place, count);
  std::vector<Piece> pieces;
  std::vector<std::pair<uint32_t, uint32_t>> free_points;  // (cavity, point on no constraint)
  std::vector<uint8_t> done(plc.num_simplices(), 0);
  const auto constraint = [&](uint32_t cav, uint32_t c) {
    const uint32_t* v = plc.simplex(c);
    pieces.push_back({cav, {v[0], v[1], v[2]}, plc.exterior_of(c)});
  };
  for (std::size_t k = 0; k < missing.size(); ++k) done[missing[k]] = 1, constraint(cavity[first_disturbed[k]], missing[k]);

  std::vector<uint8_t> on_constraint(plc.num_points(), 0);
  for (const uint32_t v : plc.simplices) on_constraint[v] = 1;
  const bool hull_domain = !plc.facet_bounded();

  // The facets between kept and cavity tetrahedra first, so that a constraint among them is not
  // also added with its own notation.
  for (uint32_t t = 0; t < tets; ++t) {
    if (place[t] != Place::Inside) continue;
    for (int i = 0; i < 4; ++i) {
      const uint32_t nb = dt.neighbors[4 * t + i], c = constraint_of_facet[4 * t + i];
      if (nb == kNone || place[nb / 4] != Place::Cavity) continue;
      if (c != kNone) {
        done[c] = 1;
        const uint32_t beyond = dt.tets[nb];  // the cavity tetrahedron's vertex off this facet
        if (side_of_constraint(plc, c, beyond) == Place::Outside) continue;
      }
      pieces.push_back(facet_with_exterior_side(plc, cavity[nb / 4], &dt.tets[4 * t], i));
    }
  }
  for (uint32_t t = 0; t < tets; ++t) {
    if (place[t] != Place::Cavity) continue;
    const uint32_t* tet = &dt.tets[4 * t];
    for (int i = 0; i < 4; ++i) {
      const uint32_t nb = dt.neighbors[4 * t + i], c = constraint_of_facet[4 * t + i];
      if (nb == kNone && hull_domain) {
        result.reaches_hull = true;
        return result;
      }
      if (c != kNone && !done[c]) done[c] = 1, constraint(cavity[t], c);
    }
    for (int k = 0; k < 4; ++k)
      if (!on_constraint[tet[k]]) free_points.emplace_back(cavity[t], tet[k]);
  }

  // One PLC per cavity; `local` is shared and reset after each.
  std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.cavity < b.cavity; });
  std::sort(free_points.begin(), free_points.end());
  result.parts.resize(count);
  std::vector<uint32_t> local(plc.num_points(), kNone), used;
  std::size_t p = 0, f = 0;
  for (uint32_t cav = 0; cav < count; ++cav) {
    CavityPlc& part = result.parts[cav];
    used.clear();
    const auto use = [&](uint32_t v) {
      if (local[v] == kNone) local[v] = 0, used.push_back(v);
    };
    const std::size_t first_piece = p;
    for (; p < pieces.size() && pieces[p].cavity == cav; ++p)
      for (const uint32_t v : pieces[p].v) use(v);
    for (; f < free_points.size() && free_points[f].first == cav; ++f) use(free_points[f].second);
    std::sort(used.begin(), used.end());
    for (uint32_t k = 0; k < used.size(); ++k) {
      local[used[k]] = k;
      part.plc.points.insert(part.plc.points.end(), plc.point(used[k]), plc.point(used[k]) + 3);
    }
    part.global = used;
    for (std::size_t q = first_piece; q < p; ++q) {
      for (const uint32_t v : pieces[q].v) part.plc.simplices.push_back(local[v]);
      part.plc.exterior.push_back(pieces[q].exterior);
    }
    for (const uint32_t v : used) local[v] = kNone;
  }
  return result;
}

}  // namespace sweepcdt::detail
