#include "sweepcdt/io/cut_away.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace sweepcdt::io {
namespace {

// Facet i of a positively oriented tetrahedron (a, b, c, d), the one opposite corner i, ordered
// counterclockwise seen from outside: orient3d(a, b, c, d) > 0 means d lies below (a, b, c) seen
// counterclockwise from above, so facet 3 is (a, b, c); the others follow by even permutations
// ((b, d, c, a), (a, c, d, b), (a, d, b, c) are positive too).
constexpr std::array<std::array<int, 3>, 4> kFacets{{{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}};

}  // namespace

CutAway cut_away(const VolumeMesh& mesh, int axis, double fraction) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("cut_away: axis must be 0, 1 or 2");
  if (!(fraction >= 0 && fraction <= 1)) throw std::invalid_argument("cut_away: fraction must be in [0, 1]");
  CutAway cut;
  const std::size_t n = mesh.num_points(), t = mesh.num_tetrahedra();
  if (n == 0) return cut;
  double lo = mesh.points[axis], hi = lo;
  for (std::size_t v = 0; v < n; ++v) {
    lo = std::min(lo, mesh.points[3 * v + axis]);
    hi = std::max(hi, mesh.points[3 * v + axis]);
  }
  cut.position = fraction == 1 ? hi : lo + fraction * (hi - lo);

  std::vector<uint8_t> kept(t, 0);
  for (std::size_t k = 0; k < t; ++k) {
    double sum = 0;
    for (int i = 0; i < 4; ++i) sum += mesh.points[3 * std::size_t{mesh.tetrahedra[4 * k + i]} + axis];
    kept[k] = fraction == 1 || sum / 4 <= cut.position;
    cut.kept_tetrahedra += kept[k];
  }

  // Every facet of every tetrahedron, keyed by its sorted corners: a facet with one tetrahedron is
  // on the domain boundary; one with two is interior.
  struct Use {
    std::array<uint32_t, 3> key;
    uint32_t tet;
    uint8_t facet;
  };
  std::vector<Use> uses;
  uses.reserve(4 * t);
  for (uint32_t k = 0; k < t; ++k)
    for (uint8_t f = 0; f < 4; ++f) {
      std::array<uint32_t, 3> key;
      for (int i = 0; i < 3; ++i) key[i] = mesh.tetrahedra[4 * std::size_t{k} + kFacets[f][i]];
      std::sort(key.begin(), key.end());
      uses.push_back({key, k, f});
    }
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) { return a.key < b.key || (a.key == b.key && a.tet < b.tet); });
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i > 2) throw std::invalid_argument("cut_away: a facet of more than two tetrahedra");
    for (std::size_t u = i; u < j; ++u) {
      const Use& use = uses[u];
      if (!kept[use.tet]) continue;
      const bool boundary = j - i == 1;
      const bool exposed = boundary || !kept[uses[u == i ? i + 1 : i].tet];
      if (!exposed) continue;
      for (int c = 0; c < 3; ++c) cut.triangles.push_back(mesh.tetrahedra[4 * std::size_t{use.tet} + kFacets[use.facet][c]]);
      cut.tetrahedron.push_back(use.tet);
      cut.on_cut.push_back(!boundary);
    }
    i = j;
  }
  return cut;
}

}  // namespace sweepcdt::io
