// Gift-wrapping (paper §2): grow a seed simplex, then finish unfinished hyperfaces one by one, each by
// the first vertex an expanding sphere touches (among those whose simplex's interior meets no
// constraining facet). O(n_v n_f n_s) with the box tree pruning the n_f factor in practice.
//
// The visibility test of §2 ("test the visibility of each vertex from the hyperface ... against each
// constraining (d-1)-simplex") is clean(): a vertex finishes a face only if the interior of the
// simplex it makes meets no constraining simplex, the paper's growth rule. Whether each grown simplex
// is constrained Delaunay (no vertex visible from its interior inside its circumsphere; if one is
// not, there is no CDT) is checked for the whole result by validate(): locally, across every facet,
// which for a triangulation is equivalent (the constrained Delaunay lemma).
#include "ids_text.h"
#include "gift_wrap.h"

#include <algorithm>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "box_tree.h"
#include "facet_hash.h"
#include "seed.h"
#include "simplex_interior.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt::detail {
namespace {

using predicates::Sign;

template <int D>
using Key = std::array<uint32_t, D>;

template <int D>
Key<D> sorted(Key<D> k) {
  sort_tuple(k);
  return k;
}

template <int D>
class GiftWrapper {
 public:
  GiftWrapper(const Plc<D>& plc, const Options& options) : plc_(plc), options_(options), reached_(plc.num_points(), 0) {
    std::vector<Box<D>> boxes(plc.num_simplices());
    for (std::size_t j = 0; j < plc.num_simplices(); ++j) {
      boxes[j] = Box<D>::of_points(constraint_coords(j).data(), D);
      Key<D> key;
      std::copy_n(plc.simplex(j), D, key.begin());
      constraint_of_.emplace(sorted<D>(key), static_cast<uint32_t>(j));
    }
    constraints_ = std::make_unique<BoxTree<D>>(std::move(boxes));
  }

  std::array<uint32_t, D + 1> first_seed() const {
    if (!plc_.facet_bounded()) return plc_.num_simplices() ? seed_from_constraint(0) : unconstrained_seed();
    std::size_t j = 0;
    while (plc_.exterior_of(j) == ExteriorSide::None) ++j;
    return seed_from_constraint(j);
  }

  Triangulation<D> run() {
    if (plc_.facet_bounded()) {
      // Paper §2 seeds from one constraining simplex; a domain of several components (disjoint
      // bodies, bodies inside cavities) needs a seed in each: every notated simplex whose domain
      // side is still unbuilt starts one.
      for (std::size_t j = 0; j < plc_.num_simplices(); ++j) {
        if (plc_.exterior_of(j) == ExteriorSide::None) continue;
        Key<D> key;
        std::copy_n(plc_.simplex(j), D, key.begin());
        if (finished_.count(sorted<D>(key))) continue;
        add_simplex(seed_from_constraint(j));
        wrap();
      }
    } else {
      add_simplex(plc_.num_simplices() ? seed_from_constraint(0) : unconstrained_seed());
      wrap();
    }
    return triangulation_of<D>(plc_, std::move(simplices_));
  }

 private:
  void wrap() {
    while (!open_.empty()) {
      const OpenFace face = open_.back();
      open_.pop_back();
      finish(face);
      // Every face: finishing one scans all vertices (O(n_v n_f) for the reference algorithm), so a
      // call per face costs nothing next to it, and Ctrl-C stops within one face's work.
      if (options_.progress && !options_.progress({"gift-wrapping", reached_count_, plc_.num_points()})) throw CancelledError();
    }
  }

  // A hyperface with one simplex built behind it: the vertices are ordered so that the side still
  // to be finished is the positive side (orient(face, x) > 0).
  struct OpenFace {
    Key<D> v;
    uint32_t behind;  // apex of the simplex already built
  };

  std::array<const double*, D> constraint_coords(std::size_t j) const {
    std::array<const double*, D> c;
    for (int i = 0; i < D; ++i) c[i] = plc_.point(plc_.simplex(j)[i]);
    return c;
  }
  predicates::Coords<D + 1> with_apex(const Key<D>& f, uint32_t v) const {
    predicates::Coords<D + 1> c;
    for (int i = 0; i < D; ++i) c[i] = plc_.point(f[i]);
    c[D] = plc_.point(v);
    return c;
  }

  // Paper §2: "let f be an arbitrary constraining (d-1)-simplex of X, and choose the direction of
  // sphere movement so the triangulation domain is immediately above f." For the convex hull, f may
  // be a hull facet: then its other side is tried.
  std::array<uint32_t, D + 1> seed_from_constraint(std::size_t j) const {
    Key<D> f;
    std::copy_n(plc_.simplex(j), D, f.begin());
    if (plc_.exterior_of(j) == ExteriorSide::Positive) std::swap(f[0], f[1]);  // domain side positive
    for (int attempt = 0; attempt < 2; ++attempt) {
      if (const uint32_t v = grow(f); v != kNone) {
        std::array<uint32_t, D + 1> s;
        std::copy(f.begin(), f.end(), s.begin());
        s[D] = v;
        return s;
      }
      if (plc_.facet_bounded())
        throw NoCdtError("gift-wrapping: no vertex can build a simplex on the domain side of constraining simplex " +
                             std::to_string(j),
                         {f.begin(), f.end()});
      std::swap(f[0], f[1]);
    }
    throw lower_dimensional();
  }

  // Without constraints: a perturbed-Delaunay simplex found by seed.h.
  std::array<uint32_t, D + 1> unconstrained_seed() const {
    const auto s = delaunay_seed<D>(plc_);
    if (!s) throw lower_dimensional();
    return *s;
  }

  static PlcError lower_dimensional() {
    return PlcError({{PlcProblemKind::LowerDimensional, {}, "the points do not span E^" + std::to_string(D)}}, 1);
  }

  // The growth procedure: among vertices strictly on f's positive side whose simplex with f is clean
  // (its interior meets no constraining simplex), the first touched by a sphere through f expanding
  // from the negative side. "w touched before v" = w inside the (perturbed) circumsphere of
  // conv(f ∪ v), a strict total order, so one scan finds the first. The first of all candidates is
  // found first, without the clean test: it is usually clean (then it is the answer), and scanning
  // with the clean test from the start costs one clean test per improvement, of big early simplices
  // whose boxes meet many constraints. Only when it is not clean does the full scan run.
  uint32_t grow(const Key<D>& f) const {
    const uint32_t first = first_touched(f, false);
    if (first == kNone || clean(f, first)) return first;
    return first_touched(f, true);
  }

  uint32_t first_touched(const Key<D>& f, bool clean_only) const {
    uint32_t best = kNone;
    predicates::Vertices<D + 1> s;
    for (int i = 0; i < D; ++i) s[i] = {plc_.point(f[i]), f[i]};
    for (uint32_t w = 0; w < plc_.num_points(); ++w) {
      if (std::count(f.begin(), f.end(), w)) continue;  // a vertex of f: flat, and exact zeros are slow
      if (predicates::orient<D>(with_apex(f, w)) != Sign::Positive) continue;
      if (best != kNone && !predicates::inside_circumsphere<D>(s, {plc_.point(w), w})) continue;
      if (clean_only && !clean(f, w)) continue;
      best = w;
      s[D] = {plc_.point(w), w};
    }
    return best;
  }

  // Does the interior of conv(f ∪ w) meet no constraining simplex?
  bool clean(const Key<D>& f, uint32_t w) const {
    const auto s = with_apex(f, w);
    return !constraints_->any_overlap(Box<D>::of_points(s.data(), D + 1), [&](uint32_t j) {
      return interior_meets<D>(s, constraint_coords(j));
    });
  }

  void finish(const OpenFace& face) {
    const Key<D> key = sorted<D>(face.v);
    if (finished_[key] >= 2) return;
    if (exterior_ahead(face, key)) {
      finished_[key] = 2;
      return;
    }
    const uint32_t v = grow(face.v);
    if (v == kNone) {
      if (!plc_.facet_bounded()) {  // nothing above a face of the convex hull
        finished_[key] = 2;
        return;
      }
      throw NoCdtError("gift-wrapping: no vertex can finish face " + ids_text(face.v.data(), D) +
                           " (no CDT exists, or the exterior notations do not enclose the domain)",
                       {face.v.begin(), face.v.end()});
    }
    std::array<uint32_t, D + 1> s;
    std::copy(face.v.begin(), face.v.end(), s.begin());
    s[D] = v;
    add_simplex(s);
  }

  // Is the face's open side the exterior side of the constraining simplex it lies on?
  bool exterior_ahead(const OpenFace& face, const Key<D>& key) const {
    const auto it = constraint_of_.find(key);
    if (it == constraint_of_.end()) return false;
    const ExteriorSide ext = plc_.exterior_of(it->second);
    if (ext == ExteriorSide::None) return false;
    Key<D> c;
    std::copy_n(plc_.simplex(it->second), D, c.begin());
    const Sign behind = predicates::orient<D>(with_apex(c, face.behind));  // side already built
    return (ext == ExteriorSide::Positive) == (behind == Sign::Negative);
  }

  // Records a positively oriented simplex and opens its hyperfaces that were not open yet.
  void add_simplex(const std::array<uint32_t, D + 1>& s) {
    simplices_.insert(simplices_.end(), s.begin(), s.end());
    for (uint32_t v : s)
      if (!reached_[v]) reached_[v] = 1, ++reached_count_;
    for (int i = 0; i <= D; ++i) {
      Key<D> g;
      for (int k = 0, j = 0; k <= D; ++k)
        if (k != i) g[j++] = s[k];
      uint8_t& count = finished_[sorted<D>(g)];
      if (count >= 2)
        throw NoCdtError("gift-wrapping: simplex " + ids_text(s.data(), D + 1) + " would be the third on face " +
                             ids_text(g.data(), D) + ": it is not constrained Delaunay, so no CDT exists",
                         {s.begin(), s.end()});
      if (++count == 2) continue;
      // Open g toward the side away from s: s[i] must end up on g's negative side.
      if (predicates::orient<D>(with_apex(g, s[i])) == Sign::Positive) std::swap(g[0], g[1]);
      open_.push_back({g, s[i]});
    }
  }

  const Plc<D>& plc_;
  const Options& options_;
  std::unique_ptr<BoxTree<D>> constraints_;
  std::unordered_map<Key<D>, uint32_t, TupleHash> constraint_of_;
  std::unordered_map<Key<D>, uint8_t, TupleHash> finished_;  // simplices built on each face so far
  std::vector<OpenFace> open_;
  std::vector<uint32_t> simplices_;
  std::vector<char> reached_;
  uint64_t reached_count_ = 0;
};

}  // namespace

template <int D>
Triangulation<D> gift_wrap(const Plc<D>& plc, const Options& options) {
  return GiftWrapper<D>(plc, options).run();
}

template <int D>
std::array<uint32_t, D + 1> seed_simplex(const Plc<D>& plc) {
  const Options options;
  return GiftWrapper<D>(plc, options).first_seed();
}

template std::array<uint32_t, 3> seed_simplex<2>(const Plc<2>&);
template std::array<uint32_t, 4> seed_simplex<3>(const Plc<3>&);
template std::array<uint32_t, 5> seed_simplex<4>(const Plc<4>&);
template std::array<uint32_t, 6> seed_simplex<5>(const Plc<5>&);
template Triangulation<2> gift_wrap<2>(const Plc<2>&, const Options&);
template Triangulation<3> gift_wrap<3>(const Plc<3>&, const Options&);
template Triangulation<4> gift_wrap<4>(const Plc<4>&, const Options&);
template Triangulation<5> gift_wrap<5>(const Plc<5>&, const Options&);

}  // namespace sweepcdt::detail
