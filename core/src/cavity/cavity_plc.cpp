#include "cavity_plc.h"

#include <algorithm>
#include <array>

#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt::detail {
namespace {

class Builder {
 public:
  explicit Builder(const Plc<3>& plc) : plc_(plc), local_(plc.num_points(), kNone) {}

  // Facet i of tetrahedron `tet`, notated with the tetrahedron's side exterior.
  void add_facet_of(const uint32_t* tet, int i) {
    std::array<uint32_t, 3> f;
    for (int k = 0, r = 0; k < 4; ++k)
      if (k != i) f[r++] = tet[k];
    const auto s = predicates::orient<3>({plc_.point(f[0]), plc_.point(f[1]), plc_.point(f[2]), plc_.point(tet[i])});
    const bool tet_positive = s == predicates::Sign::Positive;
    add(f.data(), tet_positive ? ExteriorSide::Positive : ExteriorSide::Negative);
  }

  void add(const uint32_t* v, ExteriorSide exterior) {
    for (int k = 0; k < 3; ++k) {
      simplices_.push_back(v[k]);
      use(v[k]);
    }
    exterior_.push_back(exterior);
  }

  void use(uint32_t p) { local_[p] = 0; }

  CavityPlc finish() {
    CavityPlc result;
    for (uint32_t p = 0; p < local_.size(); ++p)
      if (local_[p] != kNone) {
        local_[p] = static_cast<uint32_t>(result.global.size());
        result.global.push_back(p);
        result.plc.points.insert(result.plc.points.end(), plc_.point(p), plc_.point(p) + 3);
      }
    result.plc.simplices.reserve(simplices_.size());
    for (const uint32_t v : simplices_) result.plc.simplices.push_back(local_[v]);
    result.plc.exterior = std::move(exterior_);
    return result;
  }

 private:
  const Plc<3>& plc_;
  std::vector<uint32_t> local_;  // kNone, or 0 once used (numbered in finish())
  std::vector<uint32_t> simplices_;
  std::vector<ExteriorSide> exterior_;
};

}  // namespace

CavityPlc cavity_plc(const Plc<3>& plc, const DelaunayMesh& dt, const std::vector<uint32_t>& constraint_of_facet,
                     const std::vector<uint32_t>& missing, const std::vector<Place>& place) {
  const std::size_t tets = dt.tets.size() / 4;
  const bool hull_domain = !plc.facet_bounded();
  Builder cavity(plc);
  std::vector<uint8_t> done(plc.num_simplices(), 0);
  for (const uint32_t c : missing) done[c] = 1, cavity.add(plc.simplex(c), plc.exterior_of(c));

  std::vector<uint8_t> on_constraint(plc.num_points(), 0);
  for (const uint32_t v : plc.simplices) on_constraint[v] = 1;

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
      cavity.add_facet_of(&dt.tets[4 * t], i);
    }
  }
  for (uint32_t t = 0; t < tets; ++t) {
    if (place[t] != Place::Cavity) continue;
    const uint32_t* tet = &dt.tets[4 * t];
    for (int i = 0; i < 4; ++i) {
      const uint32_t nb = dt.neighbors[4 * t + i], c = constraint_of_facet[4 * t + i];
      if (nb == kNone && hull_domain) {
        CavityPlc result;
        result.reaches_hull = true;
        return result;
      }
      if (c != kNone && !done[c]) {
        done[c] = 1;
        cavity.add(plc.simplex(c), plc.exterior_of(c));
      }
    }
    for (int k = 0; k < 4; ++k)
      if (!on_constraint[tet[k]]) cavity.use(tet[k]);
  }
  return cavity.finish();
}

}  // namespace sweepcdt::detail
