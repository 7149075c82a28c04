#include "domain_sides.h"

#include "../parallel.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {

template <int D>
Place side_of_constraint(const Plc<D>& plc, uint32_t c, uint32_t p) {
  const ExteriorSide exterior = plc.exterior_of(c);
  if (exterior == ExteriorSide::None) return Place::Inside;
  const uint32_t* v = plc.simplex(c);
  predicates::Coords<D + 1> points;
  for (int k = 0; k < D; ++k) points[k] = plc.point(v[k]);
  points[D] = plc.point(p);
  const predicates::Sign s = predicates::orient<D>(points);
  const bool positive = s == predicates::Sign::Positive;
  return positive == (exterior == ExteriorSide::Positive) ? Place::Outside : Place::Inside;
}

template <int D>
std::vector<Place> domain_sides(const Plc<D>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& constraint_of_facet,
                                const std::vector<uint8_t>& disturbed, unsigned threads) {
  constexpr int kVertices = D + 1;
  const std::size_t simplices = dt.tets.size() / kVertices;
  std::vector<Place> place(simplices, Place::Inside);
  for (std::size_t t = 0; t < simplices; ++t)
    if (disturbed[t]) place[t] = Place::Cavity;
  if (!plc.facet_bounded()) return place;

  // Kept simplices start unplaced; seeds from the hull and the constraints, then the fill.
  std::vector<uint8_t> placed(simplices, 0);
  std::vector<uint32_t> queue;
  bool conflict = false;
  const auto put = [&](uint32_t t, Place p) {
    if (!placed[t]) {
      placed[t] = 1;
      place[t] = p;
      queue.push_back(t);
    } else if (place[t] != p) {
      conflict = true;
    }
  };
  // The seeds' sides first, in parts (an orientation per constraint facet: most of the work), then
  // placed in order as one thread would.
  constexpr uint8_t kNoSeed = 0xff;
  std::vector<uint8_t> seed(kVertices * simplices, kNoSeed);
  for_each_part(simplices, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      if (disturbed[t]) continue;
      for (int i = 0; i < kVertices; ++i) {
        const uint32_t c = constraint_of_facet[kVertices * t + i];
        if (c != kNone) seed[kVertices * t + i] = static_cast<uint8_t>(side_of_constraint(plc, c, dt.tets[kVertices * t + i]));
        else if (dt.neighbors[kVertices * t + i] == kNone) seed[kVertices * t + i] = static_cast<uint8_t>(Place::Outside);
      }
    }
  });
  for (uint32_t t = 0; t < simplices; ++t)
    for (int i = 0; i < kVertices; ++i)
      if (seed[kVertices * t + i] != kNoSeed) put(t, static_cast<Place>(seed[kVertices * t + i]));
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const uint32_t t = queue[head];
    for (int i = 0; i < kVertices; ++i) {
      const uint32_t nb = dt.neighbors[kVertices * t + i];
      if (nb == kNone || constraint_of_facet[kVertices * t + i] != kNone || disturbed[nb / kVertices]) continue;
      put(nb / kVertices, place[t]);
    }
  }
  if (conflict) return {};
  for (std::size_t t = 0; t < simplices; ++t)
    if (!disturbed[t] && !placed[t]) place[t] = Place::Cavity;
  return place;
}

#define SWEEPCDT_DOMAIN_SIDES(D)                                                                                       \
  template Place side_of_constraint<D>(const Plc<D>&, uint32_t, uint32_t);                                             \
  template std::vector<Place> domain_sides<D>(const Plc<D>&, const DelaunayMesh&, const std::vector<uint32_t>&,        \
                                              const std::vector<uint8_t>&, unsigned);
SWEEPCDT_DOMAIN_SIDES(2)
SWEEPCDT_DOMAIN_SIDES(3)
SWEEPCDT_DOMAIN_SIDES(4)
SWEEPCDT_DOMAIN_SIDES(5)
#undef SWEEPCDT_DOMAIN_SIDES

}  // namespace sweepcdt::detail
