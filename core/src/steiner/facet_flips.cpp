#include "facet_flips.h"

#include <cmath>
#include <unordered_map>

#include "facet_groups.h"
#include "../triangle_normal.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::detail {
namespace {

using predicates::Sign;
using Triangle = std::array<uint32_t, 3>;

// The auxiliary point off a facet's plane: its id only orders the perturbation, and it is never the
// decisive vertex (see facet_flips.h).
constexpr uint32_t kAuxiliaryId = kNone - 1;

class Flipper {
 public:
  // Without `delaunay_edge`: flips to each facet's CDT (in-circle); with it: flips folds to Delaunay
  // edges (flip_folds_to_delaunay).
  explicit Flipper(FacetTriangles f, const std::function<bool(uint32_t, uint32_t)>* delaunay_edge = nullptr,
                   const std::vector<char>* bent = nullptr)
      : f_(f), delaunay_edge_(delaunay_edge), bent_(bent), drop_(f.triangles.size(), -1),
        sides_(interior_edge_sides(f.triangles, f.segments, &pending_)) {}

  uint64_t run() {
    // Lawson's flips end on an exactly flat facet: an edge flipped away never comes back, so a facet
    // of k points takes at most k (k - 1) / 2 flips, whatever the triangulation it starts from (a
    // fan of long thin triangles needs about that many), and all facets together at most the sum,
    // `bound`. On a facet flat only to within rounding (folds) the in-circle test is approximate and
    // could cycle: past `bound`, flips across folds are counted, and stop at `bound` more. So flips
    // across folds cannot use up the flat facets' share, and the flips that never reach the bound pay
    // nothing to tell the two apart (an exact orientation of four nearly coplanar points each).
    // They end well before it: gearwheel_ascii.stl takes 0.98 M flips in all its rounds, against a
    // bound of 11.8 M in its first. (A cap of 10 flips per triangle, as before session 14, stopped
    // its first round at 0.73 M and cost 1349 more Steiner points.)
    const uint64_t bound = lawson_bound();
    uint64_t flips = 0, folded_past_bound = 0;
    while (!pending_.empty() && folded_past_bound <= bound) {
      const uint64_t key = pending_.back();
      pending_.pop_back();
      const auto it = sides_.find(key);
      if (it == sides_.end() || it->second[1] == kNone || !try_flip(key, it->second[0], it->second[1])) continue;
      if (++flips > bound && (delaunay_edge_ || !flat(last_flip_))) ++folded_past_bound;
    }
    return flips;
  }

 private:
  bool flat(const std::array<uint32_t, 4>& q) const {
    return predicates::orient<3>({p(q[0]), p(q[1]), p(q[2]), p(q[3])}) == Sign::Zero;
  }

  // The sum over facets of k (k - 1) / 2, k = the facet's points: triangles joined across their
  // non-segment edges are one facet, and a facet of t triangles has at most t + 2 points (Euler).
  uint64_t lawson_bound() const {
    std::vector<uint32_t> parent(f_.triangles.size());
    for (uint32_t t = 0; t < parent.size(); ++t) parent[t] = t;
    const auto root = [&](uint32_t t) {
      while (parent[t] != t) t = parent[t] = parent[parent[t]];
      return t;
    };
    for (const auto& [key, pair] : sides_)
      if (pair[1] != kNone) parent[root(pair[0])] = root(pair[1]);
    std::vector<uint64_t> size(parent.size(), 0);
    for (uint32_t t = 0; t < parent.size(); ++t) ++size[root(t)];
    uint64_t bound = 0;
    for (const uint64_t n : size)
      if (n > 0) bound += (n + 2) * (n + 1) / 2;
    return bound;
  }

  const double* p(uint32_t v) const { return f_.points.data() + 3 * std::size_t{v}; }

  bool on_common_segment(uint32_t c, uint32_t d) const {
    const auto& sc = f_.on_segment[c];
    const auto& sd = f_.on_segment[d];
    if (sc[0] != kNone && (d == sc[0] || d == sc[1] || sd == sc)) return true;
    return sd[0] != kNone && (c == sd[0] || c == sd[1]);
  }

  // The coordinate axis to drop so that the facet of triangle t projects without degeneracy.
  int drop_axis(uint32_t t) {
    int& drop = drop_[t];
    if (drop >= 0) return drop;
    const Triangle& tri = f_.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (predicates::orient_projected<3>({p(tri[0]), p(tri[1]), p(tri[2])}, k) != Sign::Zero) {
        drop = k;
        // Prefer the axis of the largest normal component (the least distorted projection).
        const int best = dominant_axis(p(tri[0]), p(tri[1]), p(tri[2]));
        if (predicates::orient_projected<3>({p(tri[0]), p(tri[1]), p(tri[2])}, best) != Sign::Zero) drop = best;
        break;
      }
    return drop;
  }

  double normal(const Triangle& t, int axis) const { return normal_component(p(t[0]), p(t[1]), p(t[2]), axis); }

  bool try_flip(uint64_t key, uint32_t t1, uint32_t t2) {
    // t1 = (a, b, c) runs a -> b; t2 must run b -> a with third vertex d.
    Triangle& s = f_.triangles[t1];
    Triangle& u = f_.triangles[t2];
    const uint32_t ka = static_cast<uint32_t>(key >> 32), kb = static_cast<uint32_t>(key);
    int i = 0;
    while (i < 3 && !((s[i] == ka || s[i] == kb) && (s[(i + 1) % 3] == ka || s[(i + 1) % 3] == kb))) ++i;
    if (i == 3) return false;
    const uint32_t a = s[i], b = s[(i + 1) % 3], c = s[(i + 2) % 3];
    int j = 0;
    while (j < 3 && !(u[j] == b && u[(j + 1) % 3] == a)) ++j;
    if (j == 3) return false;  // orientations disagree: not a facet of one orientation
    const uint32_t d = u[(j + 2) % 3];
    if (c == d || on_common_segment(c, d)) return false;
    if (delaunay_edge_ && !(*bent_)[a] && !(*bent_)[b] && !(*bent_)[c] && !(*bent_)[d]) return false;  // flat: no fold

    // Strictly convex quadrilateral a, d, b, c in the facet's plane.
    const int drop = drop_axis(t1);
    const auto o = [&](uint32_t x, uint32_t y, uint32_t z) {
      return predicates::orient_projected<3>({p(x), p(y), p(z)}, drop);
    };
    const Sign cda = o(c, d, a), cdb = o(c, d, b), abc = o(a, b, c), abd = o(a, b, d);
    if (cda == Sign::Zero || cdb == Sign::Zero || cda == cdb || abc == Sign::Zero || abd == Sign::Zero || abc == abd)
      return false;

    if (delaunay_edge_) {
      // A fold (not exactly flat) that is not Delaunay, whose other diagonal is.
      if (predicates::orient<3>({p(a), p(b), p(c), p(d)}) == Sign::Zero) return false;
      if ((*delaunay_edge_)(a, b) || !(*delaunay_edge_)(c, d)) return false;
      flip(key, t1, t2, a, b, c, d);
      return true;
    }

    // d inside the (perturbed) circumcircle of a, b, c?
    const Triangle abc_t{a, b, c};
    double e[3];
    for (int k = 0; k < 3; ++k) e[k] = p(a)[k] + normal(abc_t, k);
    if (predicates::orient<3>({p(a), p(b), p(c), e}) == Sign::Zero) return false;
    if (!predicates::inside_circumsphere<3>({{{p(a), a}, {p(b), b}, {p(c), c}, {e, kAuxiliaryId}}}, {p(d), d}))
      return false;
    flip(key, t1, t2, a, b, c, d);
    return true;
  }

  // Flips ab to cd: (c, a, d) and (d, b, c) keep the facet's orientation.
  void flip(uint64_t key, uint32_t t1, uint32_t t2, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    f_.triangles[t1] = {c, a, d};
    f_.triangles[t2] = {d, b, c};
    last_flip_ = {a, b, c, d};
    auto node = sides_.extract(key);  // the flipped edge's entry becomes the new diagonal's: no allocation
    node.key() = edge_key(c, d);
    node.mapped() = {t1, t2};
    sides_.insert(std::move(node));
    moved(edge_key(a, d), t2, t1);
    moved(edge_key(b, c), t1, t2);
    for (uint64_t k : {edge_key(c, a), edge_key(a, d), edge_key(d, b), edge_key(b, c)})
      if (sides_.count(k)) pending_.push_back(k);
  }

  // Edge `key` now belongs to triangle `to` instead of `from`.
  void moved(uint64_t key, uint32_t from, uint32_t to) {
    const auto it = sides_.find(key);
    if (it == sides_.end()) return;  // a segment
    for (uint32_t& t : it->second)
      if (t == from) t = to;
  }

  FacetTriangles f_;
  const std::function<bool(uint32_t, uint32_t)>* delaunay_edge_;
  const std::vector<char>* bent_;  // with delaunay_edge_: per point, may lie off its facets' planes
  std::array<uint32_t, 4> last_flip_{};  // the quadrilateral of the last flip
  std::vector<int> drop_;          // per triangle (its facet's projection; triangles of one facet agree)
  std::vector<uint64_t> pending_;  // declared before sides_, which fills it
  EdgeSides sides_;                // non-segment edge -> its two triangles
};

}  // namespace

uint64_t flip_facets_to_cdt(FacetTriangles facets) { return Flipper(facets).run(); }

uint64_t flip_folds_to_delaunay(FacetTriangles facets, const std::vector<char>& bent,
                                const std::function<bool(uint32_t, uint32_t)>& delaunay_edge) {
  return Flipper(facets, &delaunay_edge, &bent).run();
}

}  // namespace sweepcdt::detail
