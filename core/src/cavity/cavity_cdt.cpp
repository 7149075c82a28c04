#include "cavity_cdt.h"

#include "../facets.h"
#include "../gift_wrap.h"
#include "../sweep/sweep_cdt.h"
#include "../tuple_map.h"
#include "cavity_plc.h"
#include "disturbed.h"
#include "domain_sides.h"

namespace sweepcdt::detail {
namespace {

// Step 5: the kept tetrahedra, with their adjacency from the Delaunay mesh, and the cavities'
// simplices (in the PLC's ids), paired by their facets with each other and with the kept facets that
// face a cavity. Facets on the domain's boundary keep kNone.
Triangulation<3> assemble(const Plc<3>& plc, const DelaunayMesh& dt, const std::vector<Place>& place,
                          const std::vector<uint32_t>& cavity_simplices) {
  std::vector<uint32_t> renumbered(place.size(), kNone);
  uint32_t kept = 0;
  for (std::size_t t = 0; t < place.size(); ++t)
    if (place[t] == Place::Inside) renumbered[t] = kept++;
  Triangulation<3> tri = triangulation_of<3>(plc, {});
  tri.simplices.reserve(4 * std::size_t{kept} + cavity_simplices.size());
  tri.neighbors.reserve(tri.simplices.capacity());
  TupleMap<3> open(cavity_simplices.size());  // facet -> 4 * simplex + local index, its first side seen
  const auto pair = [&](const uint32_t* simplex, uint32_t s, int i) {
    const auto [other, first] = open.emplace(facet_key<3>(simplex, i), 4 * s + static_cast<uint32_t>(i));
    if (first) return;
    tri.neighbors[4 * s + i] = other;
    tri.neighbors[other] = 4 * s + static_cast<uint32_t>(i);
  };
  for (std::size_t t = 0; t < place.size(); ++t) {
    if (place[t] != Place::Inside) continue;
    const uint32_t s = renumbered[t];
    for (int i = 0; i < 4; ++i) {
      tri.simplices.push_back(dt.tets[4 * t + i]);
      const uint32_t nb = dt.neighbors[4 * t + i];
      const bool inside = nb != kNone && renumbered[nb / 4] != kNone;
      tri.neighbors.push_back(inside ? 4 * renumbered[nb / 4] + (nb & 3u) : kNone);
    }
    for (int i = 0; i < 4; ++i) {
      const uint32_t nb = dt.neighbors[4 * t + i];
      if (nb != kNone && place[nb / 4] == Place::Cavity) pair(&dt.tets[4 * t], s, i);
    }
  }
  for (std::size_t k = 0; k < cavity_simplices.size() / 4; ++k) {
    const uint32_t s = kept + static_cast<uint32_t>(k);
    tri.simplices.insert(tri.simplices.end(), &cavity_simplices[4 * k], &cavity_simplices[4 * k] + 4);
    tri.neighbors.insert(tri.neighbors.end(), 4, kNone);
    for (int i = 0; i < 4; ++i) pair(&cavity_simplices[4 * k], s, i);
  }
  return tri;
}

}  // namespace

std::optional<Triangulation<3>> cavity_cdt(const Plc<3>& plc, const Options& options, CdtStatistics& stats,
                                           const DelaunayMesh* delaunay) {
  const std::size_t n = plc.num_points();
  DelaunayMesh computed;
  if (!delaunay) {
    try {
      computed = delaunay_mesh(plc.points, [&](std::size_t inserted) {
        if (options.progress && !options.progress({"Delaunay", inserted, n})) throw CancelledError();
      });
    } catch (const CancelledError&) {
      throw;
    } catch (const Error&) {
      return std::nullopt;  // e.g. all points in one plane
    }
    delaunay = &computed;
  }
  const DelaunayMesh& dt = *delaunay;
  const ConstraintFaces constraints = constraint_faces(plc, dt, options.threads);
  stats.missing_constraints = constraints.missing.size();
  const Disturbed disturbed = disturbed_tetrahedra(plc, dt, constraints.missing);
  if (disturbed.tets.size() != dt.tets.size() / 4) return std::nullopt;
  const std::vector<Place> place = domain_sides(plc, dt, constraints.of_facet, disturbed.tets, options.threads);
  if (place.empty()) return std::nullopt;
  for (const Place p : place) stats.cavity_tetrahedra += p == Place::Cavity;
  const Cavities cavities = cavity_plcs(plc, dt, constraints.of_facet, constraints.missing, disturbed.first, place);
  if (cavities.reaches_hull) return std::nullopt;

  std::vector<uint32_t> cavity_simplices;
  for (const CavityPlc& cavity : cavities.parts) {
    Triangulation<3> part;
    try {
      part = sweep_cdt<3>(cavity.plc, seed_simplex(cavity.plc), options, stats);
    } catch (const NoCdtError&) {
      return std::nullopt;  // the PLC has no CDT: the whole sweep finds out again and names a witness
    }
    for (const uint32_t v : part.simplices) cavity_simplices.push_back(cavity.global[v]);
  }
  return assemble(plc, dt, place, cavity_simplices);
}

}  // namespace sweepcdt::detail
