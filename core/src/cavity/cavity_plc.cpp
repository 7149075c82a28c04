#include "cavity_plc.h"

#include <algorithm>
#include <array>

#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {
namespace {

// One constraint of a cavity PLC, in the whole PLC's ids.
template <int D>
struct Piece {
  uint32_t cavity;
  std::array<uint32_t, D> v;
  ExteriorSide exterior;
};

// The Cavity simplices' components across their facets, numbered 0.. (kNone for other places).
template <int D>
std::vector<uint32_t> cavity_of(const DelaunayMesh& dt, const std::vector<Place>& place, uint32_t& count) {
  constexpr int kVertices = D + 1;
  std::vector<uint32_t> cavity(place.size(), kNone), queue;
  count = 0;
  for (uint32_t start = 0; start < place.size(); ++start) {
    if (place[start] != Place::Cavity || cavity[start] != kNone) continue;
    cavity[start] = count;
    queue.assign(1, start);
    while (!queue.empty()) {
      const uint32_t t = queue.back();
      queue.pop_back();
      for (int i = 0; i < kVertices; ++i) {
        const uint32_t nb = dt.neighbors[kVertices * t + i];
        if (nb == kNone || place[nb / kVertices] != Place::Cavity || cavity[nb / kVertices] != kNone) continue;
        cavity[nb / kVertices] = count;
        queue.push_back(nb / kVertices);
      }
    }
    ++count;
  }
  return cavity;
}

// Facet i of simplex `tet`, notated with the simplex's side exterior.
template <int D>
Piece<D> facet_with_exterior_side(const Plc<D>& plc, uint32_t cavity, const uint32_t* tet, int i) {
  std::array<uint32_t, D> f;
  predicates::Coords<D + 1> points;
  for (int k = 0, r = 0; k <= D; ++k)
    if (k != i) points[r] = plc.point(tet[k]), f[r++] = tet[k];
  points[D] = plc.point(tet[i]);
  const auto s = predicates::orient<D>(points);
  return {cavity, f, s == predicates::Sign::Positive ? ExteriorSide::Positive : ExteriorSide::Negative};
}

}  // namespace

template <int D>
Cavities<D> cavity_plcs(const Plc<D>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& constraint_of_facet,
                        const std::vector<uint32_t>& missing, const std::vector<uint32_t>& first_disturbed,
                        const std::vector<Place>& place) {
  constexpr int kVertices = D + 1;
  const std::size_t simplices = dt.tets.size() / kVertices;
  Cavities<D> result;
  uint32_t count = 0;
  const std::vector<uint32_t> cavity = cavity_of<D>(dt, place, count);
  std::vector<Piece<D>> pieces;
  std::vector<std::pair<uint32_t, uint32_t>> free_points;  // (cavity, point on no constraint)
  std::vector<uint8_t> done(plc.num_simplices(), 0);
  const auto constraint = [&](uint32_t cav, uint32_t c) {
    Piece<D> piece{cav, {}, plc.exterior_of(c)};
    std::copy_n(plc.simplex(c), D, piece.v.begin());
    pieces.push_back(piece);
  };
  for (std::size_t k = 0; k < missing.size(); ++k) done[missing[k]] = 1, constraint(cavity[first_disturbed[k]], missing[k]);

  std::vector<uint8_t> on_constraint(plc.num_points(), 0);
  for (const uint32_t v : plc.simplices) on_constraint[v] = 1;
  const bool hull_domain = !plc.facet_bounded();

  // The facets between kept and cavity simplices first, so that a constraint among them is not
  // also added with its own notation.
  for (uint32_t t = 0; t < simplices; ++t) {
    if (place[t] != Place::Inside) continue;
    for (int i = 0; i < kVertices; ++i) {
      const uint32_t nb = dt.neighbors[kVertices * t + i], c = constraint_of_facet[kVertices * t + i];
      if (nb == kNone || place[nb / kVertices] != Place::Cavity) continue;
      if (c != kNone) {
        done[c] = 1;
        const uint32_t beyond = dt.tets[nb];  // the cavity simplex's vertex off this facet
        if (side_of_constraint(plc, c, beyond) == Place::Outside) continue;
      }
      pieces.push_back(facet_with_exterior_side<D>(plc, cavity[nb / kVertices], &dt.tets[kVertices * t], i));
    }
  }
  for (uint32_t t = 0; t < simplices; ++t) {
    if (place[t] != Place::Cavity) continue;
    const uint32_t* tet = &dt.tets[kVertices * t];
    for (int i = 0; i < kVertices; ++i) {
      const uint32_t nb = dt.neighbors[kVertices * t + i], c = constraint_of_facet[kVertices * t + i];
      if (nb == kNone && hull_domain) {
        result.reaches_hull = true;
        return result;
      }
      if (c != kNone && !done[c]) done[c] = 1, constraint(cavity[t], c);
    }
    for (int k = 0; k < kVertices; ++k)
      if (!on_constraint[tet[k]]) free_points.emplace_back(cavity[t], tet[k]);
  }

  // One PLC per cavity; `local` is shared and reset after each.
  std::stable_sort(pieces.begin(), pieces.end(), [](const Piece<D>& a, const Piece<D>& b) { return a.cavity < b.cavity; });
  std::sort(free_points.begin(), free_points.end());
  result.parts.resize(count);
  std::vector<uint32_t> local(plc.num_points(), kNone), used;
  std::size_t p = 0, f = 0;
  for (uint32_t cav = 0; cav < count; ++cav) {
    CavityPlc<D>& part = result.parts[cav];
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
      part.plc.points.insert(part.plc.points.end(), plc.point(used[k]), plc.point(used[k]) + D);
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

#define SWEEPCDT_CAVITY_PLCS(D)                                                                                        \
  template Cavities<D> cavity_plcs<D>(const Plc<D>&, const DelaunayMesh&, const std::vector<uint32_t>&,                \
                                      const std::vector<uint32_t>&, const std::vector<uint32_t>&, const std::vector<Place>&);
SWEEPCDT_CAVITY_PLCS(2)
SWEEPCDT_CAVITY_PLCS(3)
SWEEPCDT_CAVITY_PLCS(4)
SWEEPCDT_CAVITY_PLCS(5)
#undef SWEEPCDT_CAVITY_PLCS

}  // namespace sweepcdt::detail
