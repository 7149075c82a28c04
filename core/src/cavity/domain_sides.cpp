#include "domain_sides.h"

#include "../parallel.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {

Place side_of_constraint(const Plc<3>& plc, uint32_t c, uint32_t p) {
  const ExteriorSide exterior = plc.exterior_of(c);
  if (exterior == ExteriorSide::None) return Place::Inside;
  const uint32_t* v = plc.simplex(c);
  const predicates::Sign s = predicates::orient<3>({plc.point(v[0]), plc.point(v[1]), plc.point(v[2]), plc.point(p)});
  const bool positive = s == predicates::Sign::Positive;
  return positive == (exterior == ExteriorSide::Positive) ? Place::Outside : Place::Inside;
}

std::vector<Place> domain_sides(const Plc<3>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& constraint_of_facet,
                                const std::vector<uint8_t>& disturbed, unsigned threads) {
  const std::size_t tets = dt.tets.size() / 4;
  std::vector<Place> place(tets, Place::Inside);
  for (std::size_t t = 0; t < tets; ++t)
    if (disturbed[t]) place[t] = Place::Cavity;
  if (!plc.facet_bounded()) return place;

  // Kept tetrahedra start unplaced; seeds from the hull and the constraints, then the fill.
  std::vector<uint8_t> placed(tets, 0);
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
  std::vector<uint8_t> seed(4 * tets, kNoSeed);
  for_each_part(tets, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      if (disturbed[t]) continue;
      for (int i = 0; i < 4; ++i) {
        const uint32_t c = constraint_of_facet[4 * t + i];
        if (c != kNone) seed[4 * t + i] = static_cast<uint8_t>(side_of_constraint(plc, c, dt.tets[4 * t + i]));
        else if (dt.neighbors[4 * t + i] == kNone) seed[4 * t + i] = static_cast<uint8_t>(Place::Outside);
      }
    }
  });
  for (uint32_t t = 0; t < tets; ++t)
    for (int i = 0; i < 4; ++i)
      if (seed[4 * t + i] != kNoSeed) put(t, static_cast<Place>(seed[4 * t + i]));
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const uint32_t t = queue[head];
    for (int i = 0; i < 4; ++i) {
      const uint32_t nb = dt.neighbors[4 * t + i];
      if (nb == kNone || constraint_of_facet[4 * t + i] != kNone || disturbed[nb / 4]) continue;
      put(nb / 4, place[t]);
    }
  }
  if (conflict) return {};
  for (std::size_t t = 0; t < tets; ++t)
    if (!disturbed[t] && !placed[t]) place[t] = Place::Cavity;
  return place;
}

}  // namespace sweepcdt::detail
