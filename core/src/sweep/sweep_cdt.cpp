// SWEEPCDT (paper §3, Figure 13). Potential simplices — pairs of faces meeting at a reflex ridge,
// and faces with the best vertex of their drop list — wait in a priority queue ordered by
// circumcentre (plane) or power tuple (sphere), compared exactly (predicates/sweep_keys.h); each one
// popped that is still valid is constrained Delaunay (Theorem 5) and is built.
//
// The star sweep (paper §5) is the same machine run inward: the CDT of a polytope that is
// star-shaped from a point p, built in decreasing power Psi_p ("s is constructed before t if
// Psi_p(s) > Psi_p(t)"), with "behind" the side away from p. A ray from a vertex away from p strikes
// no constraint, so no vertex has a drop face: every simplex is found as a pair of faces at a ridge,
// and there is no seed.
#include "../ids_text.h"
#include "sweep_cdt.h"

#include <algorithm>
#include <memory>
#include <queue>
#include <string>

#include "../box_tree.h"
#include "../facet_hash.h"
#include "../tuple_map.h"
#include "sweep_faces.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"
#include "sweepcdt/predicates/ray.h"
#include "sweepcdt/predicates/ray_box.h"
#include "sweepcdt/predicates/rotary.h"
#include "sweepcdt/predicates/sweep_keys.h"

namespace sweepcdt::detail {
namespace {

using namespace sweep;
constexpr uint32_t kAbsent = TupleMap<1>::kAbsent;
using predicates::Side;
using predicates::Sign;

// The facet of simplex s opposite its vertex i, as a sorted key.
template <int D>
FaceKey<D> facet_opposite(const std::array<uint32_t, D + 1>& s, int i) {
  FaceKey<D> key;
  for (int k = 0, j = 0; k <= D; ++k)
    if (k != i) key[j++] = s[k];
  sort_tuple(key);
  return key;
}

// Parity of the permutation that sorts `ids`: +1 even, -1 odd.
template <std::size_t N>
int sort_parity(const std::array<uint32_t, N>& ids) {
  return odd_permutation(ids) ? -1 : 1;
}

template <int D, class Frame>
class Sweep {
  static constexpr bool kStar = std::is_same_v<Frame, predicates::StarSweep<D>>;

 public:
  Sweep(const Plc<D>& plc, const Frame& frame, const std::optional<std::array<uint32_t, D + 1>>& delta,
        const Options& options, CdtStatistics& stats, bool open = false, std::optional<NoCdtError>* failure = nullptr)
      : plc_(plc), frame_(frame), delta_(delta), options_(options), stats_(stats), open_(open), failure_(failure),
        // About two faces and three ridges per constraint (a star's link and the faces inside it),
        // so that the sweeps of small cavities do not grow their tables step by step.
        face_of_(2 * plc.num_simplices()), ridge_anchor_(3 * plc.num_simplices()),
        drop_next_(plc.num_points(), kNone), reached_(plc.num_points(), 0), queue_(ItemOrder{this}) {
    faces_.reserve(2 * plc.num_simplices());
  }

  Triangulation<D> run() {
    add_constraint_faces();
    if (delta_) add_seed(*delta_);
    link_ridge_lists();
    if constexpr (!kStar) assign_drop_faces();
    for (uint32_t f = 0; f < faces_.size(); ++f)
      if (!faces_[f].built_front) new_face(f);
    sweep();
    if (failure_ && *failure_) return {};
    if (open_) return triangulation_of<D>(plc_, std::move(simplices_));  // the caller checks the sides
    require_domain_sides_built();
    if constexpr (kStar) require_inner_sides_built();
    return triangulation_of<D>(plc_, std::move(simplices_));
  }

 private:
  // At most D + 1 faces of one simplex, without allocating (build() runs once per simplex: in the
  // star sweeps of vertex deletion, three vectors a simplex were a tenth of the sweep's time).
  struct FaceList {
    std::array<uint32_t, D + 1> ids;
    int size = 0;
    void push_back(uint32_t f) { ids[size++] = f; }
    const uint32_t* begin() const { return ids.data(); }
    const uint32_t* end() const { return ids.data() + size; }
  };

  // A potential simplex: face f with face g (a pair at a reflex ridge) or with vertex g.
  struct Item {
    std::array<uint32_t, D + 1> s;  // its vertices, positively oriented
    uint32_t f, g;
    uint32_t f_version;
    bool g_is_face;
    predicates::KeyInterval key;  // encloses the first key entry: most comparisons stop here
    mutable uint32_t words = kNone;   // star sweep: its entry in words_ once a comparison needed it
    mutable uint32_t powers = kNone;  // star sweep: its entry in powers_ once an exact comparison needed it
  };
  struct ItemOrder {
    const Sweep* sweep;
    bool operator()(const Item& a, const Item& b) const { return sweep->key_less(b, a); }  // min-heap
  };

  // A notated constraint whose domain side got no simplex: the queue ran dry before reaching it, so
  // no simplex there is constrained Delaunay — the PLC has no CDT. (Its exterior side counts as built.)
  void require_domain_sides_built() const {
    for (const Face<D>& f : faces_)
      if (f.constraint != kNone && plc_.exterior_of(f.constraint) != ExteriorSide::None && !(f.built_front && f.built_behind))
        no_cdt("no simplex on the domain side of constraining simplex " + std::to_string(f.constraint) + " " +
                   ids_text(f.v.data(), D) + ": no constrained Delaunay simplex can be built there",
               f.v.data(), D);
  }

  // In a star the constraints without notation lie inside the polytope (a facet through a deleted
  // vertex): both of their sides are domain.
  void require_inner_sides_built() const {
    for (const Face<D>& f : faces_)
      if (f.constraint != kNone && plc_.exterior_of(f.constraint) == ExteriorSide::None && !(f.built_front && f.built_behind))
        no_cdt("no simplex on one side of inner constraining simplex " + std::to_string(f.constraint) + " " +
                   ids_text(f.v.data(), D) + ": no constrained Delaunay simplex can be built there",
               f.v.data(), D);
  }

  // --- geometry ------------------------------------------------------------------------------
  const double* point(uint32_t v) const { return plc_.point(v); }
  predicates::Coords<D> coords(const FaceKey<D>& f) const {
    predicates::Coords<D> c;
    for (int i = 0; i < D; ++i) c[i] = point(f[i]);
    return c;
  }
  Side side(const FaceKey<D>& f, uint32_t p) const { return predicates::side_of<D>(frame_, coords(f), point(p)); }
  // The same for a face of the structure, from its stored front sign (no behind-side predicate).
  Side side_given_front(const FaceKey<D>& f, int8_t front, uint32_t p) const {
    predicates::Coords<D + 1> c;
    for (int i = 0; i < D; ++i) c[i] = point(f[i]);
    c[D] = point(p);
    const int o = predicates::to_int(predicates::orient<D>(c));
    return o == 0 ? Side::On : (o == front ? Side::Front : Side::Behind);
  }
  // Whether g's apex (its vertex off their shared ridge) is in front of f, and f's apex in front of g.
  bool in_front_of_each_other(const Face<D>& f, const Face<D>& g, uint32_t apex_f, uint32_t apex_g) const {
    predicates::Coords<D + 1> c;
    std::array<uint32_t, D + 1> f_then_g, g_then_f;
    for (int i = 0; i < D; ++i) c[i] = point(f.v[i]), f_then_g[i] = f.v[i], g_then_f[i] = g.v[i];
    c[D] = point(apex_g);
    f_then_g[D] = apex_g;
    g_then_f[D] = apex_f;
    const int o = predicates::to_int(predicates::orient<D>(c));  // orient(f sorted, g's apex)
    // orient(g sorted, f's apex) permutes the same points: the sign of the permutation between them.
    return o != 0 && o == f.front && o * sort_parity(f_then_g) * sort_parity(g_then_f) == g.front;
  }
  predicates::Vertices<D + 1> vertices(const std::array<uint32_t, D + 1>& s) const {
    predicates::Vertices<D + 1> v;
    for (int i = 0; i <= D; ++i) v[i] = {point(s[i]), s[i]};
    return v;
  }
  // Circumcentre order (plane) or power-tuple order (sphere): the cached enclosures first, the same
  // simplex queued twice next, the exact comparison last.
  bool key_less(const Item& a, const Item& b) const {
    if (a.key.hi < b.key.lo) return true;
    if (b.key.hi < a.key.lo) return false;
    auto sa = a.s, sb = b.s;
    sort_tuple(sa);
    sort_tuple(sb);
    if (sa == sb) return false;
    if constexpr (std::is_same_v<Frame, predicates::PlaneSweep>)
      return predicates::compare_circumcenters<D>(vertices(a.s), vertices(b.s)) == Sign::Negative;
    else if constexpr (kStar) {  // decreasing power tuples (paper §5)
      if (powers_may_differ_at_centre(a.s, b.s))
        if (const std::optional<Sign> first = predicates::power_order_from_words(words_of(b), words_of(a)))
          return (frame_.toward[0] > 0 ? *first : -*first) == Sign::Negative;
      const uint32_t pb = powers_of(b), pa = powers_of(a);  // both entries made before either is referred to
      return predicates::compare_power_sequences<D>(vertices(b.s), vertices(a.s), star_centre().data(), frame_.toward.data(), D + 2,
                                                    &powers_[pb], &powers_[pa]) == Sign::Negative;
    } else
      return predicates::compare_power_tuples<D>(vertices(a.s), vertices(b.s), vertices(*delta_)) == Sign::Negative;
  }
  // Whether to compare two items' powers at the centre by their words: not when they share a facet
  // (compare_power_sequences decides that from one insphere test) nor when the centre is on the
  // line of the edge they share (then the powers are equal: a Steiner point's own segment).
  bool powers_may_differ_at_centre(const std::array<uint32_t, D + 1>& s, const std::array<uint32_t, D + 1>& t) const {
    std::array<uint32_t, D + 1> shared;
    int n = 0;
    for (const uint32_t v : s)
      if (std::count(t.begin(), t.end(), v)) shared[n++] = v;
    if (n >= D) return false;
    return n != 2 || !predicates::collinear<D>(point(shared[0]), point(shared[1]), frame_.centre[0]);
  }
  // The double-word power of the item's simplex at the star's centre, computed on first use (a copy:
  // computing another item's may move words_).
  predicates::PowerWords words_of(const Item& item) const {
    if (item.words == kNone) {
      item.words = static_cast<uint32_t>(words_.size());
      words_.push_back(predicates::power_words<D>(vertices(item.s), frame_.centre[0]));
    }
    return words_[item.words];
  }
  // The item's entry in powers_, made on first use: what the exact comparisons work out about its
  // simplex once (predicates::PowerSequenceCache), for every later comparison of it.
  uint32_t powers_of(const Item& item) const {
    if (item.powers == kNone) {
      item.powers = static_cast<uint32_t>(powers_.size());
      powers_.emplace_back();
    }
    return item.powers;
  }
  // The star's centre p and its tie-breaking points: no vertices (their lifts cancel in power
  // comparisons, sweep_keys.h), so no ids.
  std::array<predicates::Vertex, D + 2> star_centre() const {
    std::array<predicates::Vertex, D + 2> v{};
    if constexpr (kStar)
      for (int i = 0; i < D + 2; ++i) v[i] = {frame_.centre[i], kNone};
    return v;
  }
  predicates::KeyInterval key_interval(const std::array<uint32_t, D + 1>& s) const {
    if constexpr (std::is_same_v<Frame, predicates::PlaneSweep>) {
      return predicates::circumcenter_interval<D>(vertices(s), 0);
    } else if constexpr (kStar) {  // decreasing power: the enclosure of -Psi_p
      const predicates::KeyInterval k = predicates::power_interval<D>(vertices(s), frame_.centre[0]);
      return {-k.hi, -k.lo};
    } else
      return predicates::power_interval<D>(vertices(s), point((*delta_)[0]));
  }
  // The face's vertices plus `apex`, positively oriented (apex in front of f: its side is f.front).
  std::array<uint32_t, D + 1> simplex_on_front(const Face<D>& f, uint32_t apex) const {
    std::array<uint32_t, D + 1> s{};
    std::copy(f.v.begin(), f.v.end(), s.begin());
    s[D] = apex;
    if (f.front < 0) std::swap(s[0], s[1]);
    return s;
  }
  // The sign of orient(f sorted, x) for x in front of f.
  int8_t front_sign(const FaceKey<D>& f) const {
    return static_cast<int8_t>(-predicates::to_int(predicates::behind_sign<D>(frame_, coords(f))));
  }

  [[noreturn]] void no_cdt(const std::string& what, const uint32_t* ids, int count) const {
    throw NoCdtError(std::string("sweep: ") + what, std::vector<uint32_t>(ids, ids + count));
  }

  // --- the structure ----------------------------------------------------------------------------
  uint32_t add_face(const FaceKey<D>& key) { return add_face(key, front_sign(key)); }
  uint32_t add_face(const FaceKey<D>& key, int8_t front) {
    const uint32_t id = static_cast<uint32_t>(faces_.size());
    Face<D> f;
    f.v = key;
    f.front = front;
    faces_.push_back(f);
    face_of_.emplace(key, id);
    return id;
  }

  void add_constraint_faces() {
    for (std::size_t j = 0; j < plc_.num_simplices(); ++j) {
      std::array<uint32_t, D> own;
      std::copy_n(plc_.simplex(j), D, own.begin());
      FaceKey<D> key = own;
      sort_tuple(key);
      const uint32_t id = add_face(key);
      Face<D>& f = faces_[id];
      f.constraint = static_cast<uint32_t>(j);
      const ExteriorSide ext = plc_.exterior_of(j);
      if (ext == ExteriorSide::None) continue;
      // The exterior side as a sign of orient(sorted key, x).
      const int exterior = (ext == ExteriorSide::Positive ? 1 : -1) * sort_parity(own);
      (exterior == f.front ? f.built_front : f.built_behind) = true;
    }
  }

  // The sphere's seed Delta is behind all its faces (paper §3), so each gets its behind built.
  void add_seed(const std::array<uint32_t, D + 1>& delta) {
    simplices_.insert(simplices_.end(), delta.begin(), delta.end());
    for (int i = 0; i <= D; ++i) {
      const FaceKey<D> key = facet_opposite<D>(delta, i);
      const uint32_t found = face_of_.find(key);
      const uint32_t id = found != kAbsent ? found : add_face(key);
      if (side(key, delta[i]) != Side::Behind) no_cdt("the seed simplex is not behind its face", key.data(), D);
      if (faces_[id].built_behind) no_cdt("the seed simplex lies on the exterior side of a constraint", key.data(), D);
      faces_[id].built_behind = true;
    }
  }

  // Sorts every ridge's faces by rotary order around it and links them circularly.
  // The faces are grouped by ridge with one sort, not a hash map of vectors: the star sweeps of
  // vertex deletion run this tens of thousands of times on a few dozen faces, where a vector per
  // ridge made it allocation-bound. Each ridge's list is in face order, as before.
  void link_ridge_lists() {
    std::vector<std::pair<RidgeKey<D>, uint32_t>> on;  // (ridge, face holding it)
    on.reserve(faces_.size() * D);
    for (uint32_t f = 0; f < faces_.size(); ++f)
      for (int i = 0; i < D; ++i) on.push_back({ridge_of<D>(faces_[f].v, i), f});
    std::sort(on.begin(), on.end());
    std::vector<uint32_t> list;
    for (std::size_t begin = 0, end = 0; begin < on.size(); begin = end) {
      const RidgeKey<D> ridge = on[begin].first;
      list.clear();
      for (end = begin; end < on.size() && on[end].first == ridge; ++end) list.push_back(on[end].second);
      const auto r = ridge_coords(ridge);
      const double* ref = point(apex_on(list[0], ridge));
      std::sort(list.begin() + 1, list.end(), [&](uint32_t a, uint32_t b) {
        return predicates::compare_rotary<D>(r, ref, point(apex_on(a, ridge)), point(apex_on(b, ridge))) == Sign::Negative;
      });
      for (std::size_t k = 0; k < list.size(); ++k) {
        const uint32_t a = list[k], b = list[(k + 1) % list.size()];
        faces_[a].next[ridge_index<D>(faces_[a].v, ridge)] = b;
        faces_[b].prev[ridge_index<D>(faces_[b].v, ridge)] = a;
      }
      ridge_anchor_.emplace(ridge, list[0]);
    }
  }

  predicates::Coords<D - 1> ridge_coords(const RidgeKey<D>& r) const {
    predicates::Coords<D - 1> c;
    for (int i = 0; i < D - 1; ++i) c[i] = point(r[i]);
    return c;
  }
  uint32_t apex_on(uint32_t face, const RidgeKey<D>& r) const { return faces_[face].v[ridge_index<D>(faces_[face].v, r)]; }

  // Links the new faces of simplex s into the rotary lists of their ridges. Each ridge of s lies on
  // two faces of s, and s fills the angle between them: no face of the structure lies inside it (s
  // is constrained Delaunay, Theorem 5), so where the other face is linked already, the new one goes
  // right beside it on s's side, without a rotary search (the searches were a tenth of the star
  // sweeps' time). Where it is not, the search of link_into_ridge. If no CDT exists and s is not
  // constrained Delaunay after all, the lists may come out wrong, and so does the triangulation:
  // every result of a sweep is validated (an invalid one is refused as having no CDT).
  void link_fresh_faces(const std::array<uint32_t, D + 1>& s, const std::array<uint32_t, D + 1>& face,
                        const std::array<bool, D + 1>& in_front, std::array<bool, D + 1> unlinked) {
    for (int k = 0; k <= D; ++k) {
      if (!unlinked[k]) continue;
      const uint32_t h = face[k];
      for (int i = 0; i < D; ++i) {
        // The ridge without s[k] and faces_[h].v[i]: s's other face on it is the one opposite v[i].
        const int other = static_cast<int>(std::find(s.begin(), s.end(), faces_[h].v[i]) - s.begin());
        if (unlinked[other]) {
          link_into_ridge(h, i);
          continue;
        }
        const uint32_t g = face[other];
        const int ig = ridge_index<D>(faces_[g].v, ridge_of<D>(faces_[h].v, i));
        // g's front side is its next side around the ridge when `toward` > 0 (front_neighbour).
        const bool front_is_next = ((D - 1 - ig) % 2 == 0 ? 1 : -1) * faces_[g].front > 0;
        const bool after_g = front_is_next == in_front[other];
        const uint32_t a = after_g ? g : faces_[g].prev[ig];
        const uint32_t b = after_g ? faces_[g].next[ig] : g;
        const int ia = a == g ? ig : ridge_index<D>(faces_[a].v, ridge_of<D>(faces_[h].v, i));
        const int ib = b == g ? ig : ridge_index<D>(faces_[b].v, ridge_of<D>(faces_[h].v, i));
        faces_[a].next[ia] = h;
        faces_[h].prev[i] = a;
        faces_[h].next[i] = b;
        faces_[b].prev[ib] = h;
      }
      unlinked[k] = false;
    }
  }

  // Inserts new face h into the rotary list of its ridge i (linear search for its slot).
  void link_into_ridge(uint32_t h, int i) {
    const RidgeKey<D> ridge = ridge_of<D>(faces_[h].v, i);
    const auto [anchor, fresh] = ridge_anchor_.emplace(ridge, h);
    if (fresh) {
      faces_[h].next[i] = faces_[h].prev[i] = h;
      return;
    }
    const auto r = ridge_coords(ridge);
    const double* x = point(faces_[h].v[i]);
    uint32_t a = anchor;
    // Find consecutive a -> b with x strictly between them (angles measured from a).
    for (;;) {
      const int ia = ridge_index<D>(faces_[a].v, ridge);
      const uint32_t b = faces_[a].next[ia];
      if (b == a || predicates::compare_rotary<D>(r, point(faces_[a].v[ia]), x, point(apex_on(b, ridge))) == Sign::Negative) {
        const int ib = ridge_index<D>(faces_[b].v, ridge);
        faces_[a].next[ia] = h;
        faces_[h].prev[i] = a;
        faces_[h].next[i] = b;
        faces_[b].prev[ib] = h;
        return;
      }
      a = b;
      if (a == anchor) no_cdt("a face has no place around its ridge", faces_[h].v.data(), D);
    }
  }

  // The neighbour of face f around its ridge i on f's front side.
  uint32_t front_neighbour(uint32_t f, int i) const {
    // orient(ridge sorted, apex, x) = (-1)^(D-1-i) orient(face sorted, x): moving v[i] to the end.
    const int toward = ((D - 1 - i) % 2 == 0 ? 1 : -1) * faces_[f].front;
    return toward > 0 ? faces_[f].next[i] : faces_[f].prev[i];
  }

  // --- drop faces (paper §3) --------------------------------------------------------------------
  void push_drop(uint32_t face, uint32_t v) {
    drop_next_[v] = faces_[face].drop;
    faces_[face].drop = v;
  }

  // Every vertex but Delta's: the first initial face its ray strikes.
  void assign_drop_faces() {
    std::vector<Box<D>> boxes(faces_.size());
    for (uint32_t f = 0; f < faces_.size(); ++f) boxes[f] = Box<D>::of_points(coords(faces_[f].v).data(), D);
    const BoxTree<D> tree(std::move(boxes));
    for (uint32_t v = 0; v < plc_.num_points(); ++v) {
      if (delta_ && std::count(delta_->begin(), delta_->end(), v)) continue;
      uint32_t first = kNone;
      const auto meets = [&](const Box<D>& b) { return predicates::ray_meets_box<D>(frame_, point(v), b.lo.data(), b.hi.data()); };
      tree.for_each_passing(meets, [&](uint32_t f) {
        if (std::count(faces_[f].v.begin(), faces_[f].v.end(), v)) return;  // the ray starts on f
        if (!predicates::ray_hits<D>(frame_, point(v), coords(faces_[f].v))) return;
        if (first == kNone || predicates::compare_hits<D>(frame_, point(v), coords(faces_[f].v), coords(faces_[first].v)) == Sign::Negative)
          first = f;
      });
      if (first != kNone) push_drop(first, v);
    }
  }

  // --- NEWFACE (Figure 13) -----------------------------------------------------------------------
  // Enqueues only the candidate with the least key — the paper's second inefficiency removed; if it
  // turns out stale while f is still unfinished, sweep() asks again (so a face is never left without
  // its current candidate). A pair found from both of its faces is the same simplex: equal keys, and
  // the second copy is dropped as stale.
  void new_face(uint32_t f) {
    const Face<D>& face = faces_[f];
    Item best{};
    bool have = false;
    const auto consider = [&](Item item) {
      item.key = key_interval(item.s);
      if (!have || key_less(item, best)) best = item, have = true;
    };
    for (int i = 0; i < D; ++i) {
      const uint32_t g = front_neighbour(f, i);
      if (g == f || faces_[g].built_front) continue;
      const RidgeKey<D> ridge = ridge_of<D>(face.v, i);
      const uint32_t apex_g = apex_on(g, ridge);
      // Reflex ridge: each face in front of the other. Both sides are orientations of the same D + 1
      // points (the ridge, f's apex and g's), in two orders: one exact orientation answers both.
      if (!in_front_of_each_other(face, faces_[g], face.v[i], apex_g)) continue;
      consider({simplex_on_front(face, apex_g), f, g, face.version, true, {}});
    }
    if (face.drop != kNone) consider({simplex_on_front(face, drop_candidate(f)), f, kNone, face.version, false, {}});
    if (have) {
      queue_.push(best);
      ++stats_.queue_pushes;
    }
  }

  // The drop-list vertex inside the circumsphere of conv(f ∪ v') for every other v' (transitive).
  uint32_t drop_candidate(uint32_t f) const {
    const Face<D>& face = faces_[f];
    uint32_t best = face.drop;
    for (uint32_t v = drop_next_[best]; v != kNone; v = drop_next_[v])
      if (predicates::inside_circumsphere<D>(vertices(simplex_on_front(face, best)), {point(v), v})) best = v;
    return best;
  }

  // --- the sweep ---------------------------------------------------------------------------------
  void sweep() {
    while (!queue_.empty() && !(failure_ && *failure_)) {
      const Item item = queue_.top();
      queue_.pop();
      ++stats_.queue_pops;
      if (!valid(item)) {
        ++stats_.stale_pops;
        // f's current candidate went stale (its partner was finished or is no longer its neighbour)
        // while f is still open: find f's candidate anew.
        const Face<D>& f = faces_[item.f];
        if (!f.built_front && f.version == item.f_version) new_face(item.f);
        continue;
      }
      build(item.s);
      if (options_.progress && (stats_.queue_pops & 4095) == 0 &&
          !options_.progress({"sweep", reached_count_, plc_.num_points()}))
        throw CancelledError();
    }
  }

  bool valid(const Item& item) const {
    const Face<D>& f = faces_[item.f];
    if (f.built_front || f.version != item.f_version) return false;
    if (!item.g_is_face) return true;
    if (faces_[item.g].built_front) return false;
    // Still neighbours around their shared ridge (f's one vertex not in g marks it), nothing between.
    for (int i = 0; i < D; ++i)
      if (!std::count(faces_[item.g].v.begin(), faces_[item.g].v.end(), f.v[i])) return front_neighbour(item.f, i) == item.g;
    return false;
  }

  void build(const std::array<uint32_t, D + 1>& s) {
    simplices_.insert(simplices_.end(), s.begin(), s.end());
    for (uint32_t v : s)
      if (!reached_[v]) reached_[v] = 1, ++reached_count_;
    FaceList finished, fresh, behind;  // faces s finishes, creates, lies behind
    std::array<uint32_t, D + 1> face;      // face[i]: s's face opposite s[i]
    std::array<bool, D + 1> in_front;      // whether s lies in front of it
    std::array<bool, D + 1> is_fresh{};
    for (int i = 0; i <= D; ++i) {
      const FaceKey<D> key = facet_opposite<D>(s, i);
      const uint32_t found = face_of_.find(key);
      const int8_t front = found != kAbsent ? faces_[found].front : front_sign(key);
      const Side where = side_given_front(key, front, s[i]);  // which side of the face s lies on
      face[i] = found;
      in_front[i] = where == Side::Front;
      if (found != kAbsent) {
        Face<D>& h = faces_[found];
        bool& built = where == Side::Front ? h.built_front : h.built_behind;
        if (built) no_cdt("simplex " + ids_text(s.data(), D + 1) + " overlaps another on a face: it is not constrained Delaunay", s.data(), D + 1);
        built = true;
        (where == Side::Front ? finished : behind).push_back(found);
        continue;
      }
      if (where != Side::Behind) {
        const std::string what = "simplex " + ids_text(s.data(), D + 1) + " is in front of a face built after it (Theorem 5 fails: no CDT)";
        if (!failure_) no_cdt(what, s.data(), D + 1);
        failure_->emplace("sweep: " + what, std::vector<uint32_t>(s.begin(), s.end()));
        return;  // the sweep stops (sweep() sees the failure); what this simplex began is left half done
      }
      const uint32_t h = add_face(key, front);
      faces_[h].built_behind = true;
      fresh.push_back(h);
      behind.push_back(h);
      face[i] = h;
      is_fresh[i] = true;
    }
    link_fresh_faces(s, face, in_front, is_fresh);
    if constexpr (!kStar) redistribute(s, finished, behind, fresh);
    for (uint32_t h : fresh) new_face(h);
  }

  // Paper §3: the vertices of the faces s finished move to the face their ray now strikes first: the
  // face of s the ray enters s through. A ray crosses faces from front to behind only, so that is a
  // face s lies behind — normally a new one ("find v's new drop face among F_new"); a preexisting
  // one gets a new candidate.
  void redistribute(const std::array<uint32_t, D + 1>& s, const FaceList& finished, const FaceList& behind, const FaceList& fresh) {
    FaceList touched;
    for (uint32_t f : finished) {
      uint32_t v = faces_[f].drop;
      faces_[f].drop = kNone;
      while (v != kNone) {
        const uint32_t next = drop_next_[v];
        drop_next_[v] = kNone;
        if (!std::count(s.begin(), s.end(), v)) {  // a vertex of s has entered the triangulation
          ++stats_.drop_moves;
          const uint32_t target = entry_face(s, behind, v);
          if (target == kNone) no_cdt("vertex " + std::to_string(v) + " lost its drop face", s.data(), D + 1);
          push_drop(target, v);
          if (!std::count(fresh.begin(), fresh.end(), target) && !std::count(touched.begin(), touched.end(), target))
            touched.push_back(target);
        }
        v = next;
      }
    }
    for (uint32_t h : touched) {  // preexisting faces whose drop list grew: new candidate
      ++faces_[h].version;
      new_face(h);
    }
  }

  // The face among `candidates` (faces of s that s lies behind) through which the ray from v enters
  // s: one that v sees from outside s (one orientation each); the ray test decides among several.
  uint32_t entry_face(const std::array<uint32_t, D + 1>& s, const FaceList& candidates, uint32_t v) const {
    uint32_t seen[D + 1];
    int count = 0;
    for (uint32_t h : candidates) {
      // v is beyond h iff s with h's missing vertex replaced by v is negatively oriented.
      predicates::Coords<D + 1> c;
      for (int k = 0; k <= D; ++k) c[k] = std::count(faces_[h].v.begin(), faces_[h].v.end(), s[k]) ? point(s[k]) : point(v);
      if (predicates::orient<D>(c) == Sign::Negative) seen[count++] = h;
    }
    if (count == 1) return seen[0];
    for (int k = 0; k < count; ++k)
      if (predicates::ray_hits<D>(frame_, point(v), coords(faces_[seen[k]].v))) return seen[k];
    return kNone;
  }

  const Plc<D>& plc_;
  const Frame frame_;
  const std::optional<std::array<uint32_t, D + 1>> delta_;
  const Options& options_;
  CdtStatistics& stats_;
  const bool open_;  // star sweep of a deleted hull vertex: constraints may stay without a simplex
  std::optional<NoCdtError>* const failure_;  // where to report Theorem 5 failing instead of throwing
  std::vector<Face<D>> faces_;
  TupleMap<D> face_of_;
  TupleMap<D - 1> ridge_anchor_;
  std::vector<uint32_t> drop_next_;
  std::vector<char> reached_;  // vertices of built simplices, for progress reports
  uint64_t reached_count_ = 0;
  std::priority_queue<Item, std::vector<Item>, ItemOrder> queue_;
  mutable std::vector<predicates::PowerWords> words_;  // Item::words (star sweep)
  mutable std::vector<predicates::PowerSequenceCache> powers_;  // Item::powers (star sweep)
  std::vector<uint32_t> simplices_;
};

}  // namespace

template <int D>
Triangulation<D> sweep_cdt(const Plc<D>& plc, const std::optional<std::array<uint32_t, D + 1>>& delta,
                           const Options& options, CdtStatistics& stats) {
  if (!delta) return Sweep<D, predicates::PlaneSweep>(plc, {}, delta, options, stats).run();
  predicates::SphereSweep<D> frame;
  for (int i = 0; i <= D; ++i) frame.delta[i] = plc.point((*delta)[i]);
  return Sweep<D, predicates::SphereSweep<D>>(plc, frame, delta, options, stats).run();
}

template <int D>
Triangulation<D> star_sweep_cdt(const Plc<D>& plc, const std::array<double, D>& centre, const Options& options,
                                CdtStatistics& stats, bool open, const std::array<double, D>* away,
                                std::optional<NoCdtError>* failure) {
  // Ties (faces through the centre p, equal powers) are broken as if p were moved infinitesimally
  // away from `away` (a point inside the domain, when p is on its hull), then toward q_2, q_3, ...:
  // p with its coordinate k-2 changed, so that they are affinely independent. Inside the polytope
  // any such choice gives the CDT (it is unique under the §6 perturbation).
  std::array<std::array<double, D>, D + 2> points;
  points.fill(centre);
  predicates::StarSweep<D> frame;
  for (int k = 2; k < D + 2; ++k) points[k][k - 2] = centre[k - 2] == 0 ? 1 : -centre[k - 2];
  points[1] = away ? *away : points[2];
  if (away) frame.toward[1] = -1;
  for (int k = 0; k < D + 2; ++k) frame.centre[k] = points[k].data();
  return Sweep<D, predicates::StarSweep<D>>(plc, frame, std::nullopt, options, stats, open, failure).run();
}

template Triangulation<2> star_sweep_cdt<2>(const Plc<2>&, const std::array<double, 2>&, const Options&, CdtStatistics&, bool,
                                             const std::array<double, 2>*, std::optional<NoCdtError>*);
template Triangulation<3> star_sweep_cdt<3>(const Plc<3>&, const std::array<double, 3>&, const Options&, CdtStatistics&, bool,
                                             const std::array<double, 3>*, std::optional<NoCdtError>*);
template Triangulation<4> star_sweep_cdt<4>(const Plc<4>&, const std::array<double, 4>&, const Options&, CdtStatistics&, bool,
                                             const std::array<double, 4>*, std::optional<NoCdtError>*);
template Triangulation<5> star_sweep_cdt<5>(const Plc<5>&, const std::array<double, 5>&, const Options&, CdtStatistics&, bool,
                                             const std::array<double, 5>*, std::optional<NoCdtError>*);
template Triangulation<2> sweep_cdt<2>(const Plc<2>&, const std::optional<std::array<uint32_t, 3>>&, const Options&, CdtStatistics&);
template Triangulation<3> sweep_cdt<3>(const Plc<3>&, const std::optional<std::array<uint32_t, 4>>&, const Options&, CdtStatistics&);
template Triangulation<4> sweep_cdt<4>(const Plc<4>&, const std::optional<std::array<uint32_t, 5>>&, const Options&, CdtStatistics&);
template Triangulation<5> sweep_cdt<5>(const Plc<5>&, const std::optional<std::array<uint32_t, 6>>&, const Options&, CdtStatistics&);

}  // namespace sweepcdt::detail
