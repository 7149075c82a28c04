#include "refine.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>

#include "../parallel.h"
#include "../segment_interior.h"
#include "../tuple_map.h"
#include "../delaunay/delaunay.h"
#include "../delaunay/in_background.h"
#include "../delaunay/kept_tetrahedralization.h"
#include "coordinate_set.h"
#include "facet_flips.h"
#include "facet_groups.h"
#include "spacing_grid.h"
#include "triangle_pieces.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/steiner_point.h"

namespace sweepcdt::detail {
namespace {

using Triangle = std::array<uint32_t, 3>;
using predicates::Sign;

// Limits that keep a hostile input from running away (the concentric-shell rule terminates, but the
// number of points it needs grows with the ratio of the longest segment to the smallest gap). The
// budget bounds the passes of a round (each adds a point; it looks up only the segments and
// triangles near its changes); the rounds, each a scan of
// the whole surface and a flip of its changed facets, have a limit of their own.
constexpr uint64_t kMaxRounds = 200;
// A pass (split_until_delaunay) that adds at least one point per this many triangles flips the
// facets it changed before the next pass splits them again.
constexpr std::size_t kPointsPerFlippedPass = 8;
// The point budget: 100 per input point + 100000, raised for inputs of a few thousand points to as
// much as 1000 per input point, up to 2 million. Faces flat only up to rounding and drilled (a 1.6 mm
// plate with 40 holes of 1 mm placed at an angle, 6920 points, bench/make_more_cad_parts.py) need
// 1.18 million points to make their required segments Delaunay before the deletion pass keeps
// 106796 (about 190 s, 1.4 GB): the old budget, 792000 there, refused them (exit 4). 2 million
// points hold about 2.3 GB; inputs of up to 111 points or from 19000 keep the old budget.
constexpr std::size_t kMostRaisedBudget = 2000000;
std::size_t steiner_budget(std::size_t input_points) {
  return std::max(100 * input_points + 100000, std::min(1000 * input_points, kMostRaisedBudget));
}

class Refiner {
 public:
  // `input_delaunay`: the Delaunay tetrahedralization of input.points, when an earlier refiner that
  // added no point computed it (Refinement); else the importer's, or one computed here.
  Refiner(const Plc<3>& input, const Options& options, const RequiredSegments* required, Folds folds,
          std::unique_ptr<DelaunayEdges> input_delaunay = nullptr)
      : options_(options), required_(required), folds_(folds), points_(input.points), first_delaunay_(std::move(input_delaunay)) {
    if (first_delaunay_) first_delaunay_->rebind(points_);
    // The Delaunay triangulation needs only the points: the importer may have computed it beside its
    // check (kept_tetrahedralization.h), else, given a second thread, it is computed there; either
    // way the facets are grouped meanwhile (1.3M triangles: 2.5 s beside 1.2 s).
    if (options_.steiner == SteinerMode::Auto && !first_delaunay_) imported_ = claim_kept_tetrahedralization(input);
    if (options_.steiner == SteinerMode::Auto && !first_delaunay_ && !imported_ && thread_count(options_.threads) > 1)
      helper_.emplace([this](const auto& inserted) { return std::make_unique<DelaunayEdges>(points_, inserted); });
    set_up(input);  // when it throws, helper_ is stopped as it is destroyed
  }

  // What a Refinement keeps of a refiner between attempts, beside the refined PLC it handed out, to
  // make it again for the next one (set_aside()).
  struct Kept {
    std::unique_ptr<DelaunayEdges> delaunay;  // when it added no point: its tetrahedralization of the input points, and nothing else
    std::vector<uint32_t> original;           // original_
    std::vector<double> parameter;            // parameter_
    std::vector<uint64_t> tolerated, fold_segments;  // sorted
    std::vector<uint64_t> required;                  // the input segments required then, sorted
  };
  // The refiner that handed out `last` and was set aside as `kept`, made again, with the
  // tetrahedralization `last` carries (else computed again, on a second thread while the facets are
  // grouped, given one).
  Refiner(const Plc<3>& input, const Options& options, const RequiredSegments* required, Folds folds, RefinedPlc&& last, Kept&& kept)
      : options_(options), required_(required), folds_(folds), points_(std::move(last.plc.points)) {
    if (last.delaunay) first_delaunay_ = DelaunayEdges::from_mesh(points_, *last.delaunay);
    last.delaunay.reset();
    if (!first_delaunay_ && thread_count(options_.threads) > 1)
      helper_.emplace([this](const auto& inserted) { return std::make_unique<DelaunayEdges>(points_, inserted); });
    groups_ = group_facets(input, options_.facets);
    tolerated_.insert(kept.tolerated.begin(), kept.tolerated.end());
    fold_segments_.insert(kept.fold_segments.begin(), kept.fold_segments.end());
    required_before_ = std::move(kept.required);
    r_.plc.region_seeds = input.region_seeds;
    r_.num_input_points = last.num_input_points;
    r_.facets = last.facets;
    r_.rounds = last.rounds;
    r_.flips = last.flips;
    r_.tetrahedralization_recorded = last.tetrahedralization_recorded;
    r_.steiner_on = std::move(last.steiner_on);
    r_.made_from = std::move(last.made_from);
    on_segment_.assign(r_.num_input_points, {kNone, kNone});
    on_segment_.insert(on_segment_.end(), last.on_segment.begin(), last.on_segment.end());
    parameter_ = std::move(kept.parameter);
    original_ = std::move(kept.original);
    for (std::size_t t = 0; t < last.plc.simplices.size(); t += 3)
      tris_.push_back({last.plc.simplices[t], last.plc.simplices[t + 1], last.plc.simplices[t + 2]});
    unflipped_.assign(tris_.size(), 0);  // every facet flipped at the end of the last attempt
    bent_.assign(r_.num_input_points, 0);
    for (uint32_t m = r_.num_input_points; m < points_.size() / 3; ++m) bent_.push_back(!exactly_on_its_segment(m));
    prepared_ = looked_ = continues_ = true;
    pieces_of_segments();
  }

  // groups_.segments, from the input's, for the triangles as they are: an edge of them is a piece of
  // an input segment when both its ends lie on that segment (its ends, or Steiner points on it; an
  // edge between two such points lies along it, and a triangle edge holds no point inside: its
  // triangles were split there); and the folds made segments.
  void pieces_of_segments() {
    EdgeSet pieces(fold_segments_.begin(), fold_segments_.end());
    for (const Triangle& t : tris_)
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = t[i], b = t[(i + 1) % 3];
        const std::array<uint32_t, 2> s = input_segment_of(a, b);
        const auto on = [&](uint32_t v) { return v == s[0] || v == s[1] || (!is_input(v) && on_segment_[v] == s); };
        if (s[0] != kNone && on(a) && on(b) && groups_.segments.count(edge_key(s[0], s[1]))) pieces.insert(edge_key(a, b));
      }
    groups_.segments = std::move(pieces);
  }
  ~Refiner() {
    if (imported_) imported_->helper.stop();  // claimed and never waited for: refinement failed
  }

  // What a Refinement keeps after run() to go on (above); the rest is freed with the refiner. While
  // the caller sweeps the refined PLC only that is kept: the refiner alive, with its
  // tetrahedralization, look-up tables and copies, raised the peak memory of the parts that need two
  // attempts, nearly all, by 7–23% for nothing (hollow_sphere_fine 46.6 → 57.4 MiB). A refiner that
  // added no point keeps its tetrahedralization of the input points, and the next starts from the
  // input with it, as a refinement from scratch does (the same points and triangles).
  Kept set_aside(bool added_points) {
    if (!added_points) return Kept{std::move(first_delaunay_), {}, {}, {}, {}, {}};
    Kept kept{nullptr, std::move(original_), std::move(parameter_), {tolerated_.begin(), tolerated_.end()},
              {fold_segments_.begin(), fold_segments_.end()}, {}};
    if (required_) kept.required.assign(required_->begin(), required_->end());
    for (auto* keys : {&kept.tolerated, &kept.fold_segments, &kept.required}) std::sort(keys->begin(), keys->end());
    return kept;
  }
  Refiner(const Refiner&) = delete;
  Refiner& operator=(const Refiner&) = delete;

  // Refinement::next() (refine.h): a refiner made again from what an earlier one set aside looks at
  // the segments required since, splits their pieces, and goes on from there.
  RefinedPlc run_again() {
    more_required_ = looked_;
    return run();
  }

  RefinedPlc run() {
    if (options_.steiner == SteinerMode::Auto)
      split_until_delaunay();  // flips the facets as it goes
    else
      flip_facets();
    pieces_.put_in_order();  // already: the rounds end in order
    std::vector<char> off_input = facets_off_input();
    RefinedPlc out = std::move(r_);
    out.plc.points = std::move(points_);
    out.off_input = std::move(off_input);
    out.on_segment.assign(on_segment_.begin() + out.num_input_points, on_segment_.end());
    for (std::size_t t = 0; t < tris_.size(); ++t) {
      out.plc.simplices.insert(out.plc.simplices.end(), tris_[t].begin(), tris_[t].end());
      out.plc.exterior.push_back(groups_.exterior[original_[t]]);
      // A coplanar facet's triangles no longer match input triangles: they carry the facet's first.
      out.original.push_back(options_.facets == FacetMode::Coplanar ? groups_.first_triangle[groups_.facet[original_[t]]] : original_[t]);
    }
    return out;
  }

 private:
  void set_up(const Plc<3>& input) {
    groups_ = group_facets(input, options_.facets);
    r_.plc.region_seeds = input.region_seeds;
    r_.num_input_points = static_cast<uint32_t>(input.num_points());
    r_.facets = groups_.num_facets();
    on_segment_.assign(input.num_points(), {kNone, kNone});
    bent_.assign(input.num_points(), 0);
    tris_ = groups_.triangles;
    unflipped_.assign(tris_.size(), 1);
    for (uint32_t j = 0; j < tris_.size(); ++j) original_.push_back(j);
    if (adds_points()) prepare_to_add_points();  // else nothing to look up: no segment will be split, no point made
  }

  // Every point's coordinates, and every segment in triangle order for the first look at them: once,
  // before the first round that may add points (while the tetrahedralization is computed beside).
  void prepare_to_add_points() {
    if (coordinates_.empty()) {
      coordinates_.reserve(points_.size() / 3);
      for (uint32_t v = 0; v < points_.size() / 3; ++v) coordinates_.insert(p(v));
    }
    if (prepared_) return;
    prepared_ = true;
    for_each_segment([&](uint64_t key) { first_segments_.push_back(key); }, [](uint32_t, uint32_t) { return true; });
  }

  // Whether refinement may add Steiner points: not without SteinerMode::Auto, nor when no segment
  // is required (lazy refinement's first attempt, cdt.cpp): a segment that is not required is split
  // only when it was Delaunay at first and a new point broke it (splits()), and points come only
  // from splits. Then the first round need not look the segments up at all (a tenth of the time of
  // a 327k-triangle float sphere, which needs no point).
  bool adds_points() const { return options_.steiner == SteinerMode::Auto && !(required_ && required_->empty()); }

  const double* p(uint32_t v) const { return points_.data() + 3 * std::size_t{v}; }

  // Per refined triangle: whether its facet holds a Steiner point that is not exactly on its input
  // segment, strictly inside it (rounded off it, or a point inside the facet) — RefinedPlc::off_input.
  std::vector<char> facets_off_input() const {
    std::vector<char> off_facet(groups_.num_facets(), 0);
    for (std::size_t t = 0; t < tris_.size(); ++t)
      for (const uint32_t m : tris_[t])
        if (bent_[m]) off_facet[groups_.facet[original_[t]]] = 1;
    std::vector<char> off(tris_.size());
    for (std::size_t t = 0; t < tris_.size(); ++t) off[t] = off_facet[groups_.facet[original_[t]]];
    return off;
  }
  bool exactly_on_its_segment(uint32_t m) const {
    const auto [u, v] = on_segment_[m];
    return u != kNone && strictly_inside_segment<3>(p(u), p(m), p(v));
  }
  bool is_input(uint32_t v) const { return v < r_.num_input_points; }

  // Whether the piece ab of a segment must be Delaunay: with every segment required, or when it
  // lies on a required input segment, or is a fold made a segment (or on one, inside a facet).
  bool is_required(uint32_t a, uint32_t b) const {
    if (!required_ || fold_segments_.count(edge_key(a, b))) return true;
    const std::array<uint32_t, 2> s = input_segment_of(a, b);
    return s[0] == kNone || required_->count(edge_key(s[0], s[1])) > 0;
  }

  // Whether segment `key`, which is not Delaunay, is split. With some segments required (lazy
  // refinement, cdt.cpp), one that is not is left as it is when it was not Delaunay the first time
  // it was looked at (its cavity may have a CDT all the same). A refiner that starts from the input
  // (the first attempt with points) leaves as they are the segments its points break, too: the
  // cavity sweep decides whether they matter. Splitting them there set off cascades that the CDT
  // did not need — on a band of nearly cospherical triangles each split breaks the next diagonal,
  // round the whole band: hollow_sphere_fine kept 14308 points that way, 7537 this way (TetGen -pQ:
  // 9473). A refiner that continues (a later attempt) splits what its points break, when it was
  // Delaunay until then: such a segment would otherwise show up as the next failing cavity, one
  // attempt after another (elbow_fine: more than 6 attempts without this, 3 with it).
  bool splits(uint64_t key, bool first_look) {
    if (is_required(static_cast<uint32_t>(key >> 32), static_cast<uint32_t>(key))) return true;
    if (first_look || !continues_) tolerated_.insert(key);
    return !tolerated_.count(key);
  }

  // Rounds: split every segment that is not Delaunay, then (pass after pass) those the new points
  // made not Delaunay, looking only near the points each pass changed; then give each facet its 2D
  // CDT and deal with the folds. The passes matter on bands of nearly cospherical triangles (a
  // sphere tessellated like the one around it): each split there makes the next diagonal not
  // Delaunay, one per pass, a few hundred in a row. A pass splits the triangles as a round did (in
  // the same order), without scanning every segment. It flips the facets it changed only when it
  // added many points (kPointsPerFlippedPass): a long thin facet whose two long sides are split
  // pass after pass is fanned from its two far corners, and Lawson's flips from such fans to the
  // facet's CDT number the square of its points (28.9M flips for 817k points on
  // perforated_tube_fine.stl), where flipping after each pass that halves its pieces keeps it
  // near its CDT (1.7M). An exactly flat facet's CDT is unique under the perturbation, so its
  // triangles and the points are the same either way; on facets bent by rounding (double
  // coordinates) the flips may end at another diagonal, and the counts differ slightly.
  // A pass of a few points (a cascade along a band) leaves its flips to the round's end, as
  // before: flipping costs a look at every triangle of the changed facets.
  void split_until_delaunay() {
    if (!adds_points()) {  // only the facets' 2D CDTs; the tetrahedralization waited for after them
      pieces_.put_in_order();
      flip_facets();
      r_.delaunay = first_delaunay().mesh();
      return;
    }
    prepare_to_add_points();  // a refiner made again (Refinement): the coordinates, looked up again
    DelaunayEdges& delaunay = first_delaunay();  // kept up to date as points are added
    for (;; ++r_.rounds) {
      pieces_.put_in_order();        // the last round's fold splits
      insert_new_points(delaunay);   // the Steiner points of the last round
      std::unordered_map<uint64_t, uint32_t> new_point;
      for (auto split = segments_not_in(delaunay); !split.empty(); split = changed_segments_not_in(delaunay)) {
        check_limits(split, 0);
        new_point.clear();
        for (uint64_t key : split) new_point.emplace(key, add_split_point(key, &delaunay));
        // The surface's triangles (split, and flipped after a large pass) and the tetrahedralization
        // (the new points inserted) share nothing they write: given two threads, side by side
        // (refine.h, kPointsBeside; perforated_tube_std's refinement 0.89x the time, medians of five).
        side_by_side(new_point.size() >= kPointsBeside && thread_count(options_.threads) > 1, [&] {
          split_triangles(new_point);
          if (new_point.size() * kPointsPerFlippedPass >= tris_.size()) flip_facets();
        }, [&] { insert_new_points(delaunay); });
        report_progress();
      }
      // The segments are Delaunay: give each facet its 2D CDT, then deal with the folds that
      // rounding left in it when they are not Delaunay either (see folds_not_in).
      pieces_.put_in_order();
      flip_facets();
      // Folds come from Steiner points off their segments (rounded) or inside facets: without any,
      // every facet is exactly flat (on float surfaces nearly always: refine.h), and looking for
      // folds, a map of every facet edge each round, was a tenth of perforated_tube_fine's refinement.
      if (std::none_of(bent_.begin(), bent_.end(), [](char b) { return b != 0; })) {
        r_.delaunay = delaunay.mesh();
        return;
      }
      flip_folds(delaunay);
      const std::vector<Fold> folds = folds_ == Folds::NotLookedFor ? std::vector<Fold>{} : folds_not_in(delaunay);
      if (folds.empty() || folds_ != Folds::MadeDelaunay) {
        r_.folds_left = folds.size();
        r_.delaunay = delaunay.mesh();
        return;
      }
      std::vector<uint64_t> split;
      const std::size_t inside = split_folds_inside_facets(folds, split);
      if (inside == 0 && split.empty()) split = make_segments(folds);
      check_limits(split, inside);
      report_progress();
      if (split.empty()) continue;
      new_point.clear();
      for (uint64_t key : split) new_point.emplace(key, add_split_point(key, nullptr));  // asked for by fold points: the rule without projections
      split_triangles(new_point);
    }
  }

  // The triangulation of the input points: the helper's, or computed here (also when the helper
  // failed: the same error then comes from here). Reports "Delaunay" progress meanwhile, on this
  // thread, and cancels when told to.
  DelaunayEdges& first_delaunay() {
    bool cancelled = false;
    const auto report = [&](std::size_t inserted) {
      cancelled = options_.progress && !options_.progress({"Delaunay", inserted, r_.num_input_points});
      return !cancelled;
    };
    if (imported_) {
      first_delaunay_ = wait_for_claimed(*imported_, report);
      if (first_delaunay_) first_delaunay_->rebind(points_), r_.tetrahedralization_recorded = true;
      imported_.reset();
      if (cancelled) throw CancelledError();
    }
    if (helper_) {
      if (std::unique_ptr<DelaunayEdges>* made = helper_->get(report)) first_delaunay_ = std::move(*made);
      helper_.reset();
      if (cancelled) throw CancelledError();
    }
    if (!first_delaunay_)
      first_delaunay_ = std::make_unique<DelaunayEdges>(points_, [&](std::size_t inserted) {
        if (!report(inserted)) throw CancelledError();
      });
    return *first_delaunay_;
  }

  void report_progress() const {
    if (options_.progress && !options_.progress({"steiner points", r_.steiner_on.size(), 0})) throw CancelledError();
  }

  void check_limits(const std::vector<uint64_t>& split, std::size_t inside) const {
    const bool over_budget = r_.steiner_on.size() + split.size() > steiner_budget(r_.num_input_points);
    if (!over_budget && r_.rounds < kMaxRounds) return;
    throw NoCdtError("Steiner points: " + std::to_string(split.size() + inside) + " segments or folds still not Delaunay after " +
                         std::to_string(r_.rounds) + " rounds and " + std::to_string(r_.steiner_on.size()) + " Steiner points, over " +
                         (over_budget ? "this input's limit of " + std::to_string(steiner_budget(r_.num_input_points)) +
                                            " (100 per input point + 100000, or up to 1000 per input point and 2 million)"
                                      : "the limit of " + std::to_string(kMaxRounds) + " rounds") +
                         "; long thin triangles on faces that are flat only approximately need that many" +
                         (options_.facets == FacetMode::Coplanar ? std::string() : " (faces that are exactly flat can be merged: --facets coplanar)"),
                     split.empty() ? std::vector<uint32_t>{} : std::vector<uint32_t>{static_cast<uint32_t>(split.front() >> 32), static_cast<uint32_t>(split.front())});
  }

  // The points added since the last call into `delaunay`, each located from the end of the piece
  // or fold it splits (locate_from_), not from where the last one went in.
  void insert_new_points(DelaunayEdges& delaunay) {
    const std::size_t first = points_.size() / 3 - locate_from_.size();
    delaunay.insert_new_points(
        [&](uint32_t id) { return id >= first && id - first < locate_from_.size() ? locate_from_[id - first] : kNone; });
    locate_from_.clear();
  }

  // Segments that are not Delaunay, each once, in triangle order (deterministic): a round's first
  // pass (the later ones: changed_segments_not_in). A segment checked in an earlier round and still
  // there was Delaunay then (the others were split), so only new segments and those whose ends the
  // new points' cavities touched need checking again. The first time every one is checked, from
  // the list set_up made while the tetrahedralization was computed (most of the scan's time). When a
  // Refinement continues with more segments required (refine.h), the pieces of those: the last
  // attempt ended with every other piece Delaunay or tolerated, and nothing has changed since (the
  // pieces of folds made segments are looked at too). Looking at every piece again took a quarter
  // of such an attempt on a 35k-triangle marching-tetrahedra surface that added 68 points.
  std::vector<uint64_t> segments_not_in(DelaunayEdges& delaunay) {
    std::vector<uint64_t> split;
    const auto check = [&](uint64_t key, bool first_look) {
      if (!delaunay.has_edge(static_cast<uint32_t>(key >> 32), static_cast<uint32_t>(key)) && splits(key, first_look)) split.push_back(key);
    };
    if (!looked_) {
      for (const uint64_t key : first_segments_) check(key, true);
      first_segments_ = {};
      looked_ = true;
    } else if (more_required_) {
      for_each_segment([&](uint64_t key) { check(key, false); }, [&](uint32_t a, uint32_t b) { return required_since(a, b); });
    } else {
      for_each_segment([&](uint64_t key) { check(key, false); }, [&](uint32_t a, uint32_t b) { return delaunay.may_have_changed(a, b); });
    }
    more_required_ = false;
    return split;
  }

  // Whether ab may be a piece of an input segment required since the last attempt, or of a fold.
  bool required_since(uint32_t a, uint32_t b) const {
    const std::array<uint32_t, 2> s = input_segment_of(a, b);
    if (s[0] == kNone) return true;
    const uint64_t key = edge_key(s[0], s[1]);
    return required_ && required_->count(key) && !std::binary_search(required_before_.begin(), required_before_.end(), key);
  }

  // visit(key) for each segment once, in triangle order, whose ends pass `ends(a, b)`.
  template <class Visit, class Ends>
  void for_each_segment(Visit&& visit, Ends&& ends) const {
    TupleMap<2> seen(tris_.size() * 3 / 2);  // every edge once (a flat table: 1.3M triangles made 2M nodes)
    for (const Triangle& t : tris_)
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = t[i], b = t[(i + 1) % 3];
        if (!ends(a, b) || !seen.emplace({std::min(a, b), std::max(a, b)}, 0).second) continue;
        const uint64_t key = edge_key(a, b);
        if (groups_.segments.count(key)) visit(key);
      }
  }

  // The same, after a pass: only segments with an end that the pass changed can have changed (their
  // other end changed too, or is new), in key order (deterministic).
  std::vector<uint64_t> changed_segments_not_in(DelaunayEdges& delaunay) {
    if (segment_neighbours_.empty()) {
      segment_neighbours_.resize(points_.size() / 3);
      for (const uint64_t key : groups_.segments) link_segment(key, true);
    }
    segment_neighbours_.resize(points_.size() / 3);  // points inside facets have no segment
    std::vector<uint64_t> candidates;
    for (const uint32_t v : delaunay.changed_points())
      for (const uint32_t w : segment_neighbours_[v])
        if (delaunay.may_have_changed(v, w)) candidates.push_back(edge_key(v, w));
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::vector<uint64_t> split;
    for (const uint64_t key : candidates)
      if (!delaunay.has_edge(static_cast<uint32_t>(key >> 32), static_cast<uint32_t>(key)) && splits(key, false)) split.push_back(key);
    return split;
  }

  // Segments are added and removed here, so that segment_neighbours_, once built, follows.
  void add_segment(uint64_t key) {
    if (groups_.segments.insert(key)) link_segment(key, true);
  }
  void remove_segment(uint64_t key) {
    if (groups_.segments.erase(key)) link_segment(key, false);
  }
  void link_segment(uint64_t key, bool add) {
    if (segment_neighbours_.empty()) return;
    const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
    if (segment_neighbours_.size() < points_.size() / 3) segment_neighbours_.resize(points_.size() / 3);
    for (const auto& [v, w] : {std::pair{a, b}, std::pair{b, a}}) {
      auto& list = segment_neighbours_[v];
      if (add) list.push_back(w);
      else list.erase(std::find(list.begin(), list.end(), w));
    }
  }

  // A rounded Steiner point lies a few ulps off its segment, so the triangles of one facet that meet
  // at an edge from it are not exactly coplanar: the edge is a fold, a ridge of the refined PLC like
  // any segment. The CDT theorem needs it strongly Delaunay too; a fold that is not would leave the
  // refined PLC without a CDT (thingi_1706459.stl: 20 of 11787 folds). Returns those folds, each
  // once, in triangle order, with the triangles on their sides (split_folds_inside_facets needs them,
  // and building the map of every edge of a large surface again cost as much as finding the folds).
  struct Fold {
    uint64_t key;
    std::array<uint32_t, 2> sides;
  };
  std::vector<Fold> folds_not_in(DelaunayEdges& delaunay) const {
    const EdgeSides sides = interior_edge_sides(tris_, groups_.segments);  // facet-interior edge -> its two triangles
    std::vector<Fold> folds;
    for (uint32_t j = 0; j < tris_.size(); ++j)
      for (int i = 0; i < 3; ++i) {
        const uint64_t key = edge_key(tris_[j][i], tris_[j][(i + 1) % 3]);
        const auto it = sides.find(key);
        if (it == sides.end() || it->second[0] != j || it->second[1] == kNone || delaunay.has_edge(tris_[j][i], tris_[j][(i + 1) % 3])) continue;
        const uint32_t apex = third_vertex(tris_[it->second[1]], key);
        if (predicates::orient<3>({p(tris_[j][0]), p(tris_[j][1]), p(tris_[j][2]), p(apex)}) == Sign::Zero) continue;
        folds.push_back({key, it->second});
      }
    return folds;
  }

  // Folds that are not Delaunay get a point inside their facet, at their midpoint, and the facet's
  // CDT (next round's flips) connects it to whatever it sees. A fold is typically one of a fan of
  // long thin triangles (an input vertex facing a finely split segment across a large facet), so
  // one point takes over many folds at once; splitting each fold would refine the whole facet
  // uniformly, quadratically many points. So the longest folds go first, and a midpoint closer
  // to a point placed this round than half its fold's length waits for the next round (graded, as
  // Delaunay refinement grades). Returns the number of points placed.
  std::size_t split_folds_inside_facets(const std::vector<Fold>& folds, std::vector<uint64_t>& encroached) {
    std::vector<std::tuple<double, uint64_t, std::array<uint32_t, 2>>> by_length;  // keys are distinct: the sides never decide
    for (const Fold& f : folds) by_length.emplace_back(-squared_length(f.key), f.key, f.sides);
    std::sort(by_length.begin(), by_length.end());
    std::vector<char> touched(tris_.size(), 0);
    SpacingGrid grid;
    std::unordered_map<uint64_t, uint32_t> new_point;  // fold -> its point
    for (const auto& [minus_length2, key, sides] : by_length) {
      const auto [t1, t2] = sides;
      if (touched[t1] || touched[t2]) continue;
      const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
      double x[3];
      point_on_segment(p(a), p(b), 0.5, x);
      const double radius = 0.5 * std::sqrt(-minus_length2);
      if (coordinates_.contains(x) || grid.any_within(x, radius)) continue;
      // A midpoint inside a segment's diametral ball would make that segment not Delaunay, and
      // split it next round right beside the new point: split the segment instead (Ruppert).
      bool encroaches = false;
      for (const uint32_t t : {t1, t2})
        for (int i = 0; i < 3; ++i) {
          const uint64_t side = edge_key(tris_[t][i], tris_[t][(i + 1) % 3]);
          if (!groups_.segments.count(side) || !in_diametral_ball(side, x)) continue;
          encroaches = true;
          if (std::find(encroached.begin(), encroached.end(), side) == encroached.end()) encroached.push_back(side);
        }
      if (encroaches) {
        touched[t1] = touched[t2] = 1;
        continue;
      }
      grid.add(x);
      coordinates_.insert(x);
      const uint32_t m = static_cast<uint32_t>(points_.size() / 3);
      points_.insert(points_.end(), x, x + 3);
      locate_from_.push_back(a);
      on_segment_.push_back({kNone, kNone});
      bent_.push_back(true);
      parameter_.push_back(0.0);
      r_.steiner_on.push_back(kNone);  // set by split_triangles, as for a segment's point
      r_.made_from.push_back({a, b});
      touched[t1] = touched[t2] = 1;
      new_point.emplace(key, m);
    }
    split_triangles(new_point);
    return new_point.size();
  }

  // The folds become segments (no longer flipped, split like any other segment, their split points
  // inside the facet): the way out when no fold got a point inside its facet.
  std::vector<uint64_t> make_segments(const std::vector<Fold>& folds) {
    std::vector<uint64_t> keys;
    for (const Fold& f : folds) {
      add_segment(f.key);
      fold_segments_.insert(f.key);
      keys.push_back(f.key);
    }
    return keys;
  }

  bool in_diametral_ball(uint64_t key, const double* x) const {
    const double* a = p(static_cast<uint32_t>(key >> 32));
    const double* b = p(static_cast<uint32_t>(key));
    double inner = 0;  // (a - x) . (b - x) < 0: x sees ab at an obtuse angle
    for (int k = 0; k < 3; ++k) inner += (a[k] - x[k]) * (b[k] - x[k]);
    return inner < 0;
  }

  double squared_length(uint64_t key) const {
    const double* a = p(static_cast<uint32_t>(key >> 32));
    const double* b = p(static_cast<uint32_t>(key));
    return (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]);
  }

  // Each facet to its 2D CDT — only the facets with a triangle changed since their last flips (split,
  // or flipped across a fold): flipping the others again would find nothing to flip, since Lawson's
  // flips stop only when no edge of the facet flips (or at facet_flips.cpp's bound, which no input
  // reaches). On a large surface most facets are untouched in a round; building the flips' edge map
  // and testing every edge again cost gearwheel 0.86 G of its 21.07 G instructions.
  void flip_facets() {
    std::vector<char> changed(groups_.num_facets(), 0);
    for (std::size_t t = 0; t < tris_.size(); ++t)
      if (unflipped_[t]) changed[groups_.facet[original_[t]]] = 1;
    std::vector<uint32_t> ids;
    for (uint32_t t = 0; t < tris_.size(); ++t)
      if (changed[groups_.facet[original_[t]]]) ids.push_back(t);
    std::vector<Triangle> some(ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) some[k] = tris_[ids[k]];
    r_.flips += flip_facets_to_cdt({points_, some, groups_.segments, on_segment_});
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (tris_[ids[k]] != some[k]) {
        const Triangle before = tris_[ids[k]];
        tris_[ids[k]] = some[k];
        pieces_.changed(ids[k], before);  // between passes the splits look triangles up by their points
      }
    std::fill(unflipped_.begin(), unflipped_.end(), 0);
  }

  // The folds that are not Delaunay flipped to a Delaunay diagonal where one is (facet_flips.h); the
  // triangles it changes are flipped to their facet's CDT again next round, as before. Only the
  // triangles of facets holding a bent point are handed over, in order: the others lie in their
  // facets' planes and have no fold (handing over every triangle built a map of every facet edge of
  // the surface each round: a fortieth of perforated_tube_std's run).
  void flip_folds(DelaunayEdges& delaunay) {
    const std::vector<char> bent_facet = facets_off_input();
    std::vector<uint32_t> ids;
    for (uint32_t t = 0; t < tris_.size(); ++t)
      if (bent_facet[t]) ids.push_back(t);
    std::vector<Triangle> some(ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) some[k] = tris_[ids[k]];
    r_.flips += flip_folds_to_delaunay({points_, some, groups_.segments, on_segment_}, bent_,
                                       [&](uint32_t a, uint32_t b) { return delaunay.has_edge(a, b); });
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (tris_[ids[k]] != some[k]) tris_[ids[k]] = some[k], unflipped_[ids[k]] = 1;
  }

  // Where the vertex c that encroaches the piece ab most (the largest angle acb above 90 degrees,
  // among the Delaunay neighbours of a and b) projects onto it, as a fraction of ab from a — when
  // splitting ab at its middle would not free it of c (c is in the diametral ball of the half its
  // projection falls in); else nullopt. Floating point: it only chooses where a point goes on the
  // segment, which any parameter does exactly (steiner_point.h).
  std::optional<double> encroacher_projection(uint32_t a, uint32_t b, DelaunayEdges& delaunay) {
    near_.clear();
    delaunay.link_vertices(a, near_);
    delaunay.link_vertices(b, near_);
    const double* pa = p(a);
    const double* pb = p(b);
    double least_cosine = 0;  // of the angle acb: below 0 in the diametral ball
    const double* most = nullptr;
    double fraction = 0, ab2 = 0;
    for (int k = 0; k < 3; ++k) ab2 += (pb[k] - pa[k]) * (pb[k] - pa[k]);
    for (const uint32_t c : near_) {
      if (c == a || c == b) continue;
      const double* pc = p(c);
      double dot = 0, ca2 = 0, cb2 = 0, along = 0;
      for (int k = 0; k < 3; ++k) {
        const double ca = pa[k] - pc[k], cb = pb[k] - pc[k];
        dot += ca * cb, ca2 += ca * ca, cb2 += cb * cb, along -= ca * (pb[k] - pa[k]);
      }
      const double cosine = dot / std::sqrt(ca2 * cb2);
      if (cosine < least_cosine) least_cosine = cosine, most = pc, fraction = along / ab2;
    }
    if (!most) return std::nullopt;
    const double half_centre = fraction < 0.5 ? 0.25 : 0.75;
    double to_centre2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = pa[k] + half_centre * (pb[k] - pa[k]) - most[k];
      to_centre2 += d * d;
    }
    if (to_centre2 >= ab2 / 16) return std::nullopt;  // the midpoint frees ab of c
    return fraction;
  }

  // The concentric-shell rule (refine.h, sweepcdt/steiner_point.h): returns the new point's id.
  // `delaunay` (the triangulation without this pass's points; none for the splits fold points ask
  // for) finds the encroaching vertices. A
  // point is made from its input segment's ends at its parameter along the segment when their
  // difference is exact, else (and on a fold segment) from the ends of the piece it splits.
  uint32_t add_split_point(uint64_t key, DelaunayEdges* delaunay) {
    const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
    const bool fold = fold_segments_.count(key) > 0;
    const std::array<uint32_t, 2> segment = fold ? std::array<uint32_t, 2>{kNone, kNone} : input_segment_of(a, b);
    const bool along_segment = !fold && exact_difference(p(segment[0]), p(segment[1]));
    const std::array<uint32_t, 2> ends = along_segment ? segment : std::array<uint32_t, 2>{a, b};
    double ta = along_segment ? parameter(a, segment) : 0.0, tb = along_segment ? parameter(b, segment) : 1.0;
    bool a_input = is_input(a), b_input = is_input(b);
    if (ta > tb) std::swap(ta, tb), std::swap(a_input, b_input);
    const double* u = p(ends[0]);
    const double* v = p(ends[1]);
    const double length = std::sqrt((v[0] - u[0]) * (v[0] - u[0]) + (v[1] - u[1]) * (v[1] - u[1]) + (v[2] - u[2]) * (v[2] - u[2]));
    double t = split_parameter(ta, a_input, tb, b_input, length);
    // A piece between two Steiner points is split where the vertex that encroaches it most projects
    // onto it, when the midpoint would not free the piece of that vertex and the projection is in
    // the piece's middle 80% (the reference point of Si's segment recovery, TetGen 1.5): one split
    // instead of halving towards it, and fewer points for the deletion pass to try. Pieces at an
    // input vertex keep the shells, which protect segments meeting there at small angles; a
    // segment's first split stays at its middle.
    if (delaunay && !a_input && !b_input)
      if (const std::optional<double> f = encroacher_projection(a, b, *delaunay); f && *f > 0.1 && *f < 0.9)
        t = parameter_between(along_segment ? parameter(a, segment) : 0.0, along_segment ? parameter(b, segment) : 1.0, *f);
    if (along_segment) t = parameter_exactly_on(u, v, t, ta, tb);
    double x[3];
    point_on_segment(u, v, t, x);
    // Two segments that pass within rounding of each other can get the same rounded point (a smooth
    // 120k-triangle scan did, and the Delaunay triangulation then refused the duplicate): another
    // point of the piece instead (`sweepcdt check` recognises any: sweepcdt/steiner_point.h).
    for (const double f : {0.5, 0.25, 0.75})
      if (coordinates_.contains(x)) point_on_segment(u, v, t = ta + f * (tb - ta), x);
    if (coordinates_.contains(x))
      throw NoCdtError("Steiner points: a segment is too short to split in double precision", {a, b});
    coordinates_.insert(x);
    const uint32_t m = static_cast<uint32_t>(points_.size() / 3);
    points_.insert(points_.end(), x, x + 3);
    locate_from_.push_back(a);
    on_segment_.push_back(segment);  // a fold segment's point is inside the facet, on no input segment
    bent_.push_back(!exactly_on_its_segment(m));
    parameter_.push_back(along_segment ? t : 0.0);
    // On an input segment: the first input triangle with that edge, which holds every point of it
    // (a triangle holding the piece may not: facet flips move triangles across the input triangles
    // of a coplanar facet). A fold's point lies inside a facet: split_triangles names the input
    // triangle of the first triangle holding the fold.
    r_.steiner_on.push_back(segment[0] == kNone ? kNone : first_input_triangle_with(segment[0], segment[1]));
    r_.made_from.push_back(ends);
    remove_segment(key);
    add_segment(edge_key(a, m));
    add_segment(edge_key(m, b));
    if (fold) {  // its halves are folds too
      fold_segments_.erase(key);
      fold_segments_.insert(edge_key(a, m));
      fold_segments_.insert(edge_key(m, b));
    }
    return m;
  }

  uint32_t first_input_triangle_with(uint32_t u, uint32_t v) {
    const auto key = [](uint32_t a, uint32_t b) { return std::array<uint32_t, 2>{std::min(a, b), std::max(a, b)}; };
    if (input_edge_triangle_.size() == 0)
      for (uint32_t j = 0; j < groups_.triangles.size(); ++j)  // the first one stays
        for (int i = 0; i < 3; ++i) input_edge_triangle_.emplace(key(groups_.triangles[j][i], groups_.triangles[j][(i + 1) % 3]), j);
    const uint32_t j = input_edge_triangle_.find(key(u, v));
    if (j == TupleMap<2>::kAbsent) throw std::logic_error("refine: a Steiner point's segment is no input edge");
    return j;
  }

  // A parameter near t, strictly inside (ta, tb), at which the point u + t (v - u) of a segment whose
  // difference v - u is exact comes out exact in every coordinate, so lies exactly on the segment:
  // t itself when it does, else the nearest multiple of a power of two on either side of t, on ever
  // coarser grids (fewer bits in t, so in t (v - u) and in the sum) down to a 512th of the piece. A
  // point rounded off its segment makes the facet edges from it folds, which cost rounds of fold
  // flips and fold points, and bend the facets the deletion pass must then unbend: on float surfaces
  // placed at an angle, where coordinates near 0 sit beside large ones, 1% of the points of
  // plate_with_holes_fine came out off their segments, which led to 14 rounds and 1254 points off
  // their segments or inside facets (none now: one round). Within a 512th of the piece the split
  // rule still holds, near enough (its shells agree to 2^-20 of the piece: refine.h); on float
  // coordinates a few bits fewer suffice, while on double coordinates an exact point is mostly a half
  // or a quarter of the piece, which ignores the rule (without the bound the noisy CAD parts kept up
  // to 17% more points). When no grid that fine has a point inside the piece (no coarser one can: its
  // points are the finer grid's), t stays, rounded as before.
  static constexpr double kLargestShift = 0x1p-9;
  static double parameter_exactly_on(const double* u, const double* v, double t, double ta, double tb) {
    if (exact_point_on_segment(u, v, t)) return t;
    for (int bits = 52; bits > 0; --bits) {
      const double quantum = std::ldexp(1.0, -bits);  // t / quantum and back are exact: powers of two
      if (quantum > (tb - ta) * kLargestShift) break;
      const double below = std::floor(t / quantum) * quantum, above = std::ceil(t / quantum) * quantum;
      const bool below_inside = below > ta, above_inside = above < tb;
      if (!below_inside && !above_inside) break;
      const bool below_first = t - below <= above - t;
      for (const double c : {below_first ? below : above, below_first ? above : below})
        if ((c == below ? below_inside : above_inside) && exact_point_on_segment(u, v, c)) return c;
    }
    return t;
  }
  // Whether every coordinate of point_on_segment(u, v, t) is exact, v - u being exact: the product
  // exact (its FMA remainder zero, away from underflow, where a remainder can vanish by rounding)
  // and the sum exact.
  static bool exact_point_on_segment(const double* u, const double* v, double t) {
    for (int k = 0; k < 3; ++k) {
      const double d = v[k] - u[k], product = t * d;
      if (d != 0 && (std::fabs(product) < 0x1p-900 || std::fma(t, d, -product) != 0)) return false;
      if (!sum_is_exact(u[k], product)) return false;
    }
    return true;
  }
  // Whether a + b is exact in double: Knuth's TwoSum, whose rounding error is itself exact, is zero.
  static bool sum_is_exact(double a, double b) {
    const double sum = a + b, back = sum - a;
    return (a - (sum - back)) + (b - back) == 0;
  }

  // Whether v - u is exact in double in every coordinate (Knuth's TwoSum: the rounding error of
  // the difference, itself exact). When it is not, the rounded points u + t (v - u) lie near a line
  // that is not uv — one that can pass exactly through another vertex that uv misses, so that
  // splitting never makes the segment Delaunay (Steiner.SplitPointThatRoundsOntoAnotherPoint).
  static bool exact_difference(const double* u, const double* v) {
    for (int k = 0; k < 3; ++k)
      if (!sum_is_exact(v[k], -u[k])) return false;
    return true;
  }

  // The input segment (its ends, the smaller id first) that the piece ab of a segment lies on.
  std::array<uint32_t, 2> input_segment_of(uint32_t a, uint32_t b) const {
    if (!is_input(a)) return on_segment_[a];
    if (!is_input(b)) return on_segment_[b];
    return {std::min(a, b), std::max(a, b)};
  }
  // Where point w of an input segment lies along it: 0 at its first end, 1 at its second.
  double parameter(uint32_t w, const std::array<uint32_t, 2>& ends) const {
    return is_input(w) ? (w == ends[0] ? 0.0 : 1.0) : parameter_[w - r_.num_input_points];
  }

  // Every triangle split along each of its split edges in turn, keeping its orientation and facet
  // (triangle_pieces.h: the new pieces in order only when put_in_order() is called).
  void split_triangles(const std::unordered_map<uint64_t, uint32_t>& new_point) {
    pieces_.split(new_point, points_.size() / 3, r_.steiner_on, r_.num_input_points);
  }

  const Options& options_;
  const RequiredSegments* required_;  // null: every segment
  const Folds folds_;
  std::vector<double> points_;  // first: the helper thread reads it from the start
  std::unique_ptr<DelaunayEdges> first_delaunay_;  // kept up to date through the rounds
  std::shared_ptr<KeptTetrahedralization> imported_;  // the importer's, claimed, until first_delaunay() waits for it
  std::optional<InBackground<std::unique_ptr<DelaunayEdges>>> helper_;  // after points_, which it reads
  FacetGroups groups_;
  RefinedPlc r_;
  std::vector<std::array<uint32_t, 2>> on_segment_;  // per point: the input segment it lies on (input points: none)
  std::vector<double> parameter_;  // per Steiner point: its t along on_segment_ (sweepcdt/steiner_point.h)
  std::vector<Triangle> tris_;
  std::vector<uint32_t> original_;  // per triangle: the input triangle it lies in
  std::vector<char> unflipped_;      // per triangle: new, or changed, since the facets' last flips
  TrianglePieces pieces_{tris_, original_, unflipped_};  // splits them; in order after put_in_order()
  std::vector<std::vector<uint32_t>> segment_neighbours_;  // per point, its segments' other ends (once a round needs a second pass)
  bool prepared_ = false;                 // prepare_to_add_points() has run
  std::vector<uint64_t> first_segments_;  // every segment once, in triangle order, for the first round
  bool looked_ = false;                   // the first round has looked at every segment
  bool more_required_ = false;            // run_again(): look at the segments required since (segments_not_in)
  std::vector<uint64_t> required_before_;  // sorted: the input segments required in the last attempt
  std::vector<uint32_t> locate_from_;     // per point added since the tetrahedralization took the last ones: an end of what it split
  bool continues_ = false;                // made again from what an earlier refiner set aside (splits())
  EdgeSet tolerated_;  // not required and not Delaunay when first looked at, or broken by a first refiner (splits())
  // Per point: a Steiner point not exactly on its input segment, or inside a facet (the others lie in
  // the planes of the facets that hold them).
  std::vector<char> bent_;
  std::vector<uint32_t> near_;  // encroacher_projection's candidates
  TupleMap<2> input_edge_triangle_;  // input edge (its ends, sorted) -> its first input triangle
  EdgeSet fold_segments_;  // folds made segments (fold_edges_not_in), and their halves
  CoordinateSet coordinates_;  // every point's, bit for bit
};

}  // namespace

RefinedPlc refine(const Plc<3>& input, const Options& options, const RequiredSegments* required, Folds folds) {
  return Refiner(input, options, required, folds).run();
}

struct Refinement::Impl {
  const Plc<3>& input;
  const Options& options;
  const RequiredSegments& required;
  std::optional<Refiner::Kept> kept;  // by the last attempt's refiner
};

Refinement::Refinement(const Plc<3>& input, const Options& options, const RequiredSegments& required)
    : impl_(std::make_unique<Impl>(Impl{input, options, required, {}})) {}
Refinement::~Refinement() = default;

RefinedPlc Refinement::next(RefinedPlc&& last) {
  Impl& m = *impl_;
  std::unique_ptr<Refiner> refiner;
  if (!m.kept || m.kept->delaunay) {  // the first attempt, or one after an attempt that added no point
    last = {};  // freed first: its tetrahedralization is as large as the one kept
    refiner = std::make_unique<Refiner>(m.input, m.options, &m.required, Folds::NotLookedFor, m.kept ? std::move(m.kept->delaunay) : nullptr);
  } else {
    refiner = std::make_unique<Refiner>(m.input, m.options, &m.required, Folds::NotLookedFor, std::move(last), std::move(*m.kept));
    last = {};
  }
  m.kept.reset();
  RefinedPlc refined = refiner->run_again();
  m.kept = refiner->set_aside(!refined.steiner_on.empty());
  return refined;
}

}  // namespace sweepcdt::detail
