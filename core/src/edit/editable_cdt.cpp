// EditableCdt (sweepcdt/editable_cdt.h): vertex deletion by the star CDT of paper §5.
//
// The structure is the Triangulation's flat arrays with free slots: simplices and neighbours as in
// triangulation.h (a deleted simplex has kNone as its first vertex and its slot is reused), one
// simplex per vertex to start walks from, and the constraints with a per-vertex index.
#include "sweepcdt/editable_cdt.h"

#include <algorithm>
#include <climits>
#include <exception>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "../facet_hash.h"
#include "../ids_text.h"
#include "../segment_interior.h"
#include "../sweep/sweep_cdt.h"
#include "../tuple_map.h"
#include "blocked_segment.h"
#include "sheets.h"
#include "sorted_keys.h"
#include "star_fill.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt {

using detail::TupleHash;
using predicates::Sign;

namespace {

// An empty set of ids (simplex slots, vertex ids) for a star, one per thread and Kind, reused:
// deletions are worked out on several threads at once (remove_steiner.cpp), and a map constructed
// for each star, whose simplices number hundreds on thin walls, spent a tenth of a deletion's plan on
// perforated_tube_std allocating and growing. The map keeps the capacity a star needed (emptying it
// costs that much), unless one star made it very large; one set of a Kind at a time on a thread:
// the next call empties it.
enum MarkKind { kStarSimplices, kStarVertices };
template <int Kind>
detail::TupleMap<1>& empty_star_set() {
  constexpr std::size_t kSmall = 256, kLarge = std::size_t{1} << 16;
  thread_local detail::TupleMap<1> set(kSmall);
  if (set.capacity() > kLarge) set = detail::TupleMap<1>(kSmall);
  else set.clear();
  return set;
}

}  // namespace

template <int D>
struct EditableCdt<D>::Impl {
  using Key = std::array<uint32_t, D>;  // a facet, sorted

  // --- vertices ---
  std::vector<double> points;
  uint32_t num_input_points = 0;
  std::vector<uint32_t> steiner_on;
  std::vector<uint32_t> rank;    // the triangulation's perturbation_rank (may be empty)
  std::vector<char> alive;
  std::vector<uint32_t> simplex_at;  // per vertex: a live simplex holding it
  std::size_t live_vertices = 0;

  // --- simplices ---
  std::vector<uint32_t> simplices, neighbors;
  std::vector<int32_t> regions;
  std::vector<uint32_t> free_slots;
  std::size_t live_simplices = 0;

  // --- constraints ---
  std::vector<std::array<uint32_t, D>> constraints;
  std::vector<ExteriorSide> exterior;  // empty when the PLC has no notations
  std::vector<uint32_t> tags;          // one per constraint (all 0 when the PLC has none: has_tags)
  bool has_tags = false;
  bool unbend = false;                 // unbend_facets_at_steiner_points()
  std::size_t unbend_largest_star = 0;
  std::vector<char> flat_by_tag;        // EditableCdt::know_flat_facets()
  bool guess_blocked_refusals = false;  // EditableCdt::guess_blocked_refusals()
  unsigned growth_factor = 0;           // EditableCdt::limit_growth()
  std::vector<char> constraint_alive;
  std::vector<std::vector<uint32_t>> constraints_at;  // per vertex, the live ones
  detail::TupleMap<D> constraint_of;  // sorted facet -> its live constraint
  std::vector<RegionSeed<D>> region_seeds;

  // --- plans (EditableCdt::plan_removal) ---
  // Deletions applied so far: each deletes a vertex, so 32 bits hold them, and a stamp per simplex
  // slot costs 4 bytes, not 8 (37 MB of the fine perforated tube's 9M tetrahedra).
  uint32_t commits = 0;
  std::vector<uint32_t> changed_at;  // per simplex slot: the commit that last changed it (0: none)
  uint64_t redone = 0;               // plans worked out again because a commit changed what they read
  uint64_t refused_early = 0;        // refusals applied that early_refusal() found

  const double* point(uint32_t v) const { return points.data() + std::size_t{v} * D; }
  uint32_t order(uint32_t v) const { return rank.empty() ? v : rank[v]; }
  predicates::Vertex vertex(uint32_t v) const { return {point(v), order(v)}; }
  uint32_t* simplex(uint32_t t) { return simplices.data() + std::size_t{t} * (D + 1); }
  const uint32_t* simplex(uint32_t t) const { return simplices.data() + std::size_t{t} * (D + 1); }
  static Key sorted(Key k) {
    detail::sort_tuple(k);
    return k;
  }
  // The facet of simplex t of `tri` opposite its vertex i, in the simplex's order.
  static Key facet_of(const Triangulation<D>& tri, uint32_t t, int i) {
    Key f;
    for (int k = 0, j = 0; k <= D; ++k)
      if (k != i) f[j++] = tri.simplex(t)[k];
    return f;
  }
  // The facet of simplex t opposite its vertex i, in the simplex's order.
  Key facet(uint32_t t, int i) const {
    Key f;
    for (int k = 0, j = 0; k <= D; ++k)
      if (k != i) f[j++] = simplex(t)[k];
    return f;
  }

  void add_constraint(const Key& c, ExteriorSide side, uint32_t tag) {
    const uint32_t id = static_cast<uint32_t>(constraints.size());
    constraints.push_back(c);
    if (!exterior.empty() || side != ExteriorSide::None) {
      exterior.resize(constraints.size() - 1, ExteriorSide::None);
      exterior.push_back(side);
    }
    tags.push_back(tag);  // dropped again in the end when the PLC has none
    constraint_alive.push_back(1);
    for (uint32_t v : c) constraints_at[v].push_back(id);
    constraint_of.emplace(sorted(c), id);
  }

  Impl(Plc<D> plc, Triangulation<D> tri)
      : points(std::move(tri.points)), num_input_points(tri.num_input_points), steiner_on(std::move(tri.steiner_on)),
        rank(std::move(tri.perturbation_rank)), simplices(std::move(tri.simplices)), neighbors(std::move(tri.neighbors)),
        regions(std::move(tri.regions)), live_simplices(simplices.size() / (D + 1)), constraint_of(plc.num_simplices()),
        region_seeds(std::move(plc.region_seeds)) {
    const std::size_t n = points.size() / D;
    alive.assign(n, 0);
    simplex_at.assign(n, kNone);
    constraints_at.resize(n);
    changed_at.assign(live_simplices, 0);
    for (uint32_t t = 0; t < live_simplices; ++t)
      for (int i = 0; i <= D; ++i) {
        const uint32_t v = simplex(t)[i];
        if (!alive[v]) alive[v] = 1, ++live_vertices;
        simplex_at[v] = t;
      }
    for (std::size_t j = 0; j < plc.num_simplices(); ++j) {
      Key c;
      std::copy_n(plc.simplex(j), D, c.begin());
      add_constraint(c, plc.exterior_of(j), plc.tags.empty() ? 0 : plc.tags[j]);
    }
    has_tags = !plc.tags.empty();
  }

  const std::vector<uint32_t>& live_constraints_at(uint32_t v) const { return constraints_at[v]; }

  // The facets through v, each without v (the paper's recursion): indices into `through`.
  // Throws VertexRemovalError when v cannot go, or, given `refusal`, says why there.
  std::vector<detail::Sheet<D>> sheets_through(uint32_t v, const std::vector<uint32_t>& through, std::string* refusal = nullptr) const {
    std::vector<Key> keys;
    for (uint32_t c : through) keys.push_back(constraints[c]);
    // Unbending, tags name input facets: an edge is on a facet's boundary when pieces of two hold it.
    std::optional<detail::Unbend> unbending;
    if (D == 3 && unbend && has_tags && v >= num_input_points)
      unbending = detail::Unbend{num_input_points, [&](uint32_t a, uint32_t b) {
                                   uint32_t tag = kNone;
                                   for (uint32_t c : constraints_at[a])
                                     if (std::count(constraints[c].begin(), constraints[c].end(), b)) {
                                       if (tag != kNone && tags[c] != tag) return true;
                                       tag = tags[c];
                                     }
                                   return false;
                                 }};
    return detail::sheets_without<D>(
        v, keys, [&](uint32_t x) { return point(x); }, [&](uint32_t x) { return order(x); },
        [&](uint32_t a, uint32_t b) { return !has_tags || tags[through[a]] == tags[through[b]]; }, unbending ? &*unbending : nullptr,
        refusal);
  }

  // Why v's bent sheets may not be filled (unbend_facets_at_steiner_points: its star is too large), or "".
  std::string star_too_large_to_unbend(uint32_t v, const std::vector<detail::Sheet<D>>& sheets, std::size_t star_size) const {
    if (star_size <= unbend_largest_star || std::none_of(sheets.begin(), sheets.end(), [](const auto& s) { return s.bent; })) return {};
    return too_large_to_unbend(v, star_size);
  }
  std::string too_large_to_unbend(uint32_t v, std::size_t star_size) const {
    return "vertex " + std::to_string(v) + " cannot be deleted: its facets are bent by rounding and its star has " + std::to_string(star_size) +
           " simplices (at most " + std::to_string(unbend_largest_star) + ")";
  }

  void require_vertex(uint32_t v) const {
    if (v >= alive.size() || !alive[v]) throw VertexRemovalError("vertex " + std::to_string(v) + " is not a vertex of the triangulation");
  }

  // --- the star of v -----------------------------------------------------------------------------
  std::vector<uint32_t> star_of(uint32_t v) const {
    std::vector<uint32_t> star{simplex_at[v]};
    detail::TupleMap<1>& seen = empty_star_set<kStarSimplices>();
    seen.emplace({star[0]}, 0);
    for (std::size_t k = 0; k < star.size(); ++k) {
      const uint32_t t = star[k];
      for (int i = 0; i <= D; ++i) {
        const uint32_t across = neighbors[std::size_t{t} * (D + 1) + i];
        if (simplex(t)[i] == v || across == kNone) continue;  // the link face, or the domain's boundary
        if (seen.emplace({across / (D + 1)}, 0).second) star.push_back(across / (D + 1));
      }
    }
    return star;
  }

  static NoCdtError no_cdt_error(uint32_t v, const std::string& why, std::vector<uint32_t> witness) {
    return NoCdtError("deleting vertex " + std::to_string(v) + " leaves a PLC without a CDT: " + why, std::move(witness));
  }
  [[noreturn]] void no_cdt(uint32_t v, const std::string& why, std::vector<uint32_t> witness) const {
    throw no_cdt_error(v, why, std::move(witness));
  }

  // --- the segment a Steiner point's deletion merges ------------------------------------------------
  // v's two neighbours on the segment it lies on: the ends of the edges from v that lie on pieces of
  // two input facets (tags name input facets while unbending), when there are exactly two.
  std::optional<std::array<uint32_t, 2>> segment_neighbours(uint32_t v) const {
    std::vector<std::pair<uint32_t, uint32_t>> ends;  // (neighbour, tag of a constraint through both)
    for (const uint32_t c : constraints_at[v])
      for (const uint32_t w : constraints[c])
        if (w != v) ends.push_back({w, tags[c]});
    std::sort(ends.begin(), ends.end());
    std::array<uint32_t, 2> found;
    std::size_t count = 0;
    for (std::size_t i = 0; i < ends.size();) {
      std::size_t j = i + 1;
      while (j < ends.size() && ends[j].first == ends[i].first) ++j;
      if (ends[j - 1].second != ends[i].second) {  // two tags: a ridge
        if (count == 2) return std::nullopt;
        found[count++] = ends[i].first;
      }
      i = j;
    }
    if (count != 2) return std::nullopt;
    return found;
  }

  // Whether the pieces of each input facet through v lie in one plane (exactly): its sheet is flat.
  // Each piece's vertices are tested against the plane of its facet's first piece through v.
  bool flat_pieces_at(uint32_t v) const requires(D == 3) {
    const std::vector<uint32_t>& through = constraints_at[v];
    if (std::all_of(through.begin(), through.end(), [&](uint32_t c) { return tags[c] < flat_by_tag.size() && flat_by_tag[tags[c]]; }))
      return true;
    for (std::size_t i = 0; i < through.size(); ++i) {
      const uint32_t tag = tags[through[i]];
      if (std::any_of(through.begin(), through.begin() + i, [&](uint32_t c) { return tags[c] == tag; })) continue;  // not the first
      const Key& first = constraints[through[i]];
      for (std::size_t j = i + 1; j < through.size(); ++j) {
        if (tags[through[j]] != tag) continue;
        for (const uint32_t w : constraints[through[j]])
          if (std::find(first.begin(), first.end(), w) == first.end() &&
              predicates::orient<3>({point(first[0]), point(first[1]), point(first[2]), point(w)}) != predicates::Sign::Zero)
            return false;
      }
    }
    return true;
  }

  // A refusal of v's deletion found before its sheets and cavity are built, or null. Only while
  // unbending (the deletion pass: tags name input facets), for a Steiner point on a segment (not on
  // the hull), between its two neighbours a and b there:
  // - rounded off ab with a star too large to unbend: a sheet closed by ab is bent, so
  //   star_too_large_to_unbend() would refuse it once the sheets are built (VertexRemovalError);
  // - exactly on ab, each input facet's pieces around it exactly flat, and its two pieces would merge
  //   into one that every sphere through a and b holds a vertex of v's star in (blocked_segment.h):
  //   that vertex is visible from v, a point of ab (the new facets through ab cover what the old
  //   pieces did), so ab is not constrained Delaunay and the star sweep would find no CDT (NoCdtError
  //   with the witness a, b and three vertices one of which every sphere through a and b holds: while
  //   those five stay the refusal stands — a deletion adds vertices to v's star and takes none away
  //   but the one deleted — so the deletion pass does not try v again when another neighbour goes;
  //   should a deletion bend v's pieces, the same test refuses v as a guess, below). On float
  //   surfaces nearly every refusal is of this kind (pipe_tee_std: 5252 of 5272).
  // - off ab, or in bent pieces, with the same test failing: v may see past the new facets, so this
  //   proves nothing (14 of 2252 such refusals on bracket_fine with rounding noise were deletions the
  //   star sweep accepts), and it is refused only when asked to guess (guess_blocked_refusals:
  //   VertexRemovalError). On double surfaces most refusals are of this kind: gearwheel_ascii.stl's
  //   star sweep refused 33973 deletions that the test blocks and 11 that it does not, and accepted
  //   22244, none of them blocked (session 30).
  std::exception_ptr early_refusal(uint32_t v, const std::vector<uint32_t>& star, bool on_hull, std::vector<uint32_t>& witness) const {
    if constexpr (D != 3) {
      return {};
    } else {
      if (!unbend || !has_tags || v < num_input_points || on_hull) return {};
      const std::optional<std::array<uint32_t, 2>> ends = segment_neighbours(v);
      if (!ends) return {};
      const auto [a, b] = *ends;
      const bool on_segment = detail::strictly_inside_segment<D>(point(a), point(v), point(b));
      if (!on_segment && star.size() > unbend_largest_star) return std::make_exception_ptr(VertexRemovalError(too_large_to_unbend(v, star.size())));
      const bool proves = on_segment && flat_pieces_at(v);
      if (!proves && !guess_blocked_refusals) return {};
      // The star's other vertices, each once, as the star lists them (any order decides the same).
      std::vector<uint32_t> ids;
      ids.reserve(star.size());
      detail::TupleMap<1>& seen = empty_star_set<kStarVertices>();
      for (const uint32_t t : star)
        for (int i = 0; i <= D; ++i)
          if (const uint32_t x = simplex(t)[i]; x != v && x != a && x != b && seen.emplace({x}, 0).second) ids.push_back(x);
      std::vector<predicates::Vertex> others;
      others.reserve(ids.size());
      for (const uint32_t x : ids) others.push_back({point(x), order(x)});
      const detail::BlockedSegment blocked = detail::segment_in_spheres({point(a), order(a)}, {point(b), order(b)}, others);
      if (blocked.answer != detail::SegmentInSpheres::Blocked) return {};
      const auto [e, c, d] = blocked.witness;
      if (!proves)
        return std::make_exception_ptr(VertexRemovalError(
            "vertex " + std::to_string(v) + " is kept: the segment " + std::to_string(a) + "-" + std::to_string(b) +
            " its deletion would leave is not Delaunay (every sphere through its ends holds vertex " + std::to_string(ids[e]) + ", " +
            std::to_string(ids[c]) + " or " + std::to_string(ids[d]) + "), and it lies off that segment or its facets are bent there"));
      witness = {a, b, ids[e], ids[c], ids[d]};
      return std::make_exception_ptr(no_cdt_error(v,
                                                  "the segment " + std::to_string(a) + "-" + std::to_string(b) +
                                                      " it would leave is not Delaunay (every sphere through its ends holds vertex " +
                                                      std::to_string(ids[e]) + ", " + std::to_string(ids[c]) + " or " + std::to_string(ids[d]) + ")",
                                                  witness));
    }
  }

  // --- deletion -----------------------------------------------------------------------------------
  struct LinkFace {
    Key key;          // sorted, global ids
    uint32_t across;  // the neighbour outside the cavity (encoded as in neighbors), or kNone
    int32_t region;   // of the star simplex it bounded
  };
  struct NewConstraint {
    Key key;
    ExteriorSide plc_side;  // its notation in the PLC
    uint32_t tag;
  };
  // How a deletion's new simplices join the rest of the mesh, worked out with its plan (on whichever
  // thread plans it) so that the commit, one at a time in list order, only writes: the look-ups,
  // sorts and region walk were a third of the deletion pass's serial part (perforated_tube_std).
  static constexpr int32_t kRegionAsItIs = INT32_MIN;  // a new simplex no region reaches: its slot's value stays
  struct Wiring {
    // Per facet of a new simplex (t * (D + 1) + i) with no new simplex across: the link face it
    // lies on (index into the plan's link), or kNone (a sheet's simplex on the domain's boundary).
    std::vector<uint32_t> link_face;
    std::vector<uint32_t> uncovered;  // link faces with a simplex across that no new simplex reached (v on the hull)
    // (vertex, link face): a vertex of that face, with a simplex across, in no new simplex; it walks
    // from the simplex across (its old one may be a star slot, freed or reused). In link order.
    std::vector<std::pair<uint32_t, uint32_t>> outside_only;
    std::vector<int32_t> region;  // per new simplex, when the mesh has regions (or kRegionAsItIs)
  };

  // A deletion worked out and not yet applied (EditableCdt::Removal), or the error it met.
  struct Plan {
    uint32_t v = kNone;
    uint32_t epoch = 0;             // `commits` when it was made
    // The slots of v's star. A plan also reads the simplices across the star's faces, but a commit
    // that changes one of those changes (its neighbour link to) the star simplex beside it too.
    std::vector<uint32_t> read;
    bool read_beyond = false;       // v on the hull: its checks walked further
    std::exception_ptr error;
    bool refused = false;  // the error is NoCdtError or VertexRemovalError
    std::vector<uint32_t> witness;  // a NoCdtError's (global ids)
    std::vector<uint32_t> star, through, ids;
    Triangulation<D> fill;
    std::vector<LinkFace> link;
    std::vector<NewConstraint> added;
    Wiring wiring;
    bool early = false;  // refused by early_refusal()
  };

  // Reads only: plans of several vertices may be made at once (commits change what they read).
  Plan plan(uint32_t v) const {
    Plan p;
    p.v = v;
    p.epoch = commits;
    try {
      work_out(p);
    } catch (const NoCdtError& e) {
      p.error = std::current_exception();
      p.refused = true;
      p.witness = e.witness();
    } catch (const VertexRemovalError&) {
      p.error = std::current_exception();
      p.refused = true;
    } catch (...) {
      p.error = std::current_exception();
    }
    return p;
  }

  // A commit since p was made changed a simplex p read (or may have: p walked beyond its star, or
  // the triangulation is nearly empty, where the vertex count decides).
  bool stale(const Plan& p) const {
    if (p.epoch == commits) return false;
    if (p.read_beyond || p.read.empty() || live_vertices <= D + 2) return true;
    return std::any_of(p.read.begin(), p.read.end(), [&](uint32_t t) { return changed_at[t] > p.epoch; });
  }

  // Applies p, worked out again first if stale: false when the deletion is refused (NoCdtError,
  // VertexRemovalError) and `throw_refusal` is off (the NoCdtError's witness then in `witness`, if
  // given), else v's former neighbours in `neighbours`.
  bool apply(Plan p, std::vector<uint32_t>& neighbours, bool throw_refusal, std::vector<uint32_t>* witness = nullptr) {
    if (stale(p)) {
      ++redone;
      p = plan(p.v);
    }
    refused_early += p.early;
    if (p.refused && !throw_refusal) {
      if (witness) *witness = std::move(p.witness);
      return false;
    }
    if (p.error) std::rethrow_exception(p.error);
    commit(p);
    std::sort(p.ids.begin(), p.ids.end());  // ascending, as neighbours() lists them
    neighbours = std::move(p.ids);
    return true;
  }
  std::vector<uint32_t> apply(Plan p) {
    std::vector<uint32_t> neighbours;
    apply(std::move(p), neighbours, true);
    return neighbours;
  }

  std::vector<uint32_t> remove_vertex(uint32_t v) { return apply(plan(v)); }

  void work_out(Plan& p) const {
    const uint32_t v = p.v;
    require_vertex(v);
    if (live_vertices <= D + 1) throw VertexRemovalError("vertex " + std::to_string(v) + " cannot be deleted: the triangulation would be empty");
    const std::vector<uint32_t> star = star_of(v);
    p.read = star;

    // Boundary faces through v that are no constraints: v is on a convex-hull domain's boundary, and
    // the cavity is open there (paper §5: the algorithm "works correctly even if v lies on the
    // boundary of the CDT"); the new hull is checked after the sweep.
    bool on_hull = false;
    for (uint32_t t : star)
      for (int i = 0; i <= D; ++i)
        if (simplex(t)[i] != v && neighbors[std::size_t{t} * (D + 1) + i] == kNone && !constraint_of.contains(sorted(facet(t, i))))
          on_hull = true;

    p.read_beyond = on_hull;
    if ((p.error = early_refusal(v, star, on_hull, p.witness))) {
      p.refused = p.early = true;
      return;
    }
    // The facets through v, each without v (the paper's recursion).
    const std::vector<uint32_t> through = live_constraints_at(v);
    std::string refusal;  // most refused Steiner points: reported without unwinding
    const auto sheets = sheets_through(v, through, &refusal);
    if (refusal.empty()) refusal = star_too_large_to_unbend(v, sheets, star.size());
    if (!refusal.empty()) {
      p.error = std::make_exception_ptr(VertexRemovalError(refusal));
      p.refused = true;
      return;
    }

    // The cavity as a PLC on the link's vertices, numbered in perturbation order.
    std::vector<uint32_t> ids;
    ids.reserve(star.size() * D);
    for (uint32_t t : star)
      for (int i = 0; i <= D; ++i)
        if (simplex(t)[i] != v) ids.push_back(simplex(t)[i]);
    std::sort(ids.begin(), ids.end(), [&](uint32_t a, uint32_t b) { return order(a) < order(b); });
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<std::pair<uint32_t, uint32_t>> local;  // (global id, cavity id), sorted
    Plc<D> cavity;
    cavity.points.reserve(ids.size() * D);
    for (uint32_t x : ids) {
      local.push_back({x, static_cast<uint32_t>(cavity.num_points())});
      cavity.points.insert(cavity.points.end(), point(x), point(x) + D);
    }
    std::sort(local.begin(), local.end());
    const auto add = [&](const Key& global, ExteriorSide side) {
      for (uint32_t x : global) {
        const auto it = std::lower_bound(local.begin(), local.end(), std::pair{x, 0u});
        if (it == local.end() || it->first != x) throw std::logic_error("vertex deletion: a cavity face has a vertex off the link");
        cavity.simplices.push_back(it->second);
      }
      cavity.exterior.push_back(side);
    };
    // The link: v's side is inside. Facet i of a positive simplex has v (its vertex i) on the side
    // of sign (-1)^(D-i).
    std::vector<LinkFace> link;
    link.reserve(star.size());
    cavity.simplices.reserve(3 * star.size() * D);  // the link and about as much again for the sheets
    cavity.exterior.reserve(3 * star.size());
    for (uint32_t t : star)
      for (int i = 0; i <= D; ++i)
        if (simplex(t)[i] == v) {
          add(facet(t, i), (D - i) % 2 == 0 ? ExteriorSide::Negative : ExteriorSide::Positive);
          link.push_back({sorted(facet(t, i)), neighbors[std::size_t{t} * (D + 1) + i], regions.empty() ? 0 : regions[t]});
        }
    // The sheets' new simplices: inner facets of the cavity, or its boundary where the star lies on
    // one side of the sheet only (v on the domain's boundary).
    std::vector<NewConstraint> added;
    for (const auto& sheet : sheets) {
      const uint32_t c0 = through[sheet.constraints.front()];
      const ExteriorSide in_cavity = cavity_side(star, constraints[c0]);
      const ExteriorSide in_plc = exterior.empty() ? ExteriorSide::None : exterior[c0];
      for (const Key& s : sheet.fill) {
        add(s, in_cavity);
        added.push_back({s, in_plc, tags[c0]});
      }
    }

    // Paper §5: the inward sweep from v, then the exact checks.
    CdtStatistics stats;
    Triangulation<D> fill;
    std::array<double, D> centre;
    std::copy_n(point(v), D, centre.begin());
    // The sweep's error in the vertex ids of the whole.
    const auto cavity_error = [&](const NoCdtError& e) {
      std::vector<uint32_t> witness;
      for (uint32_t x : e.witness()) witness.push_back(x < ids.size() ? ids[x] : x);
      return no_cdt_error(v, e.what(), std::move(witness));
    };
    std::optional<NoCdtError> failed;  // most refusals: reported without unwinding
    try {
      std::array<double, D> inside;
      if (on_hull) inside = point_inside_hull_left(v, star);
      fill = detail::star_sweep_cdt<D>(cavity, centre, Options{}, stats, on_hull, on_hull ? &inside : nullptr, &failed);
    } catch (const NoCdtError& e) {
      throw cavity_error(e);
    }
    if (failed) {
      NoCdtError error = cavity_error(*failed);
      p.witness = error.witness();
      p.error = std::make_exception_ptr(std::move(error));
      p.refused = true;
      return;
    }
    if (growth_factor > 0 && fill.num_simplices() > growth_factor * star.size() + 8) {
      p.error = std::make_exception_ptr(VertexRemovalError("vertex " + std::to_string(v) + " is kept: its cavity's CDT has " +
                                                           std::to_string(fill.num_simplices()) + " simplices, its star " +
                                                           std::to_string(star.size()) + " (limit_growth)"));
      p.refused = true;
      return;
    }
    if (!on_hull) {
      const std::string failure = detail::check_star_fill(fill, cavity);  // validate()'s verdict, for a star (and the neighbours)
      if (!failure.empty()) no_cdt(v, "the cavity's triangulation fails validation (" + failure + ")", {});
    } else {
      compute_neighbors(fill);
      if (fill.num_simplices() == 0 && live_simplices == star.size())
        throw VertexRemovalError("vertex " + std::to_string(v) + " cannot be deleted: the points left span no " + std::to_string(D) + "-dimensional simplex");
      const Plc<D> region = closed_over_new_hull(v, cavity, fill, added.size());
      if (fill.num_simplices() > 0) {  // on the hull the star may just vanish (its link faces become hull)
        const ValidationReport report = validate(fill, region);
        if (!report.ok())
          no_cdt(v, "the cavity's triangulation fails validation (" + report.failures.front().check + ": " + report.failures.front().detail + ")", {});
      }
    }
    for (uint32_t& x : fill.simplices) x = ids[x];
    p.wiring = wire(fill, link, added);
    check_link_delaunay(v, fill, link, p.wiring);
    if (on_hull) {
      check_new_hull(v, star, fill, link);
      require_link_vertices_kept(v, ids, fill, link);
    }
    p.star = star;
    p.through = through;
    p.ids = std::move(ids);
    p.fill = std::move(fill);
    p.link = std::move(link);
    p.added = std::move(added);
  }

  // --- a vertex on the convex hull ------------------------------------------------------------------
  // A point strictly inside the convex hull of the vertices but v: the rounded centroid of a
  // D-simplex of them (a star simplex with v swapped for another link vertex), checked exactly to lie
  // strictly inside it.
  std::array<double, D> point_inside_hull_left(uint32_t v, const std::vector<uint32_t>& star) const {
    // First a simplex outside the star: across a link face.
    for (uint32_t t : star)
      for (int i = 0; i <= D; ++i) {
        const uint32_t across = neighbors[std::size_t{t} * (D + 1) + i];
        if (simplex(t)[i] != v || across == kNone) continue;
        std::array<uint32_t, D + 1> sigma;
        std::copy_n(simplex(across / (D + 1)), D + 1, sigma.begin());
        if (const auto c = centroid_strictly_inside(sigma)) return *c;
      }
    for (uint32_t t : star) {
      for (uint32_t u : star)
        for (int j = 0; j <= D; ++j) {
          const uint32_t w = simplex(u)[j];
          if (w == v || std::count(simplex(t), simplex(t) + D + 1, w)) continue;
          std::array<uint32_t, D + 1> sigma;
          std::copy_n(simplex(t), D + 1, sigma.begin());
          *std::find(sigma.begin(), sigma.end(), v) = w;
          if (const auto c = centroid_strictly_inside(sigma)) return *c;
        }
    }
    throw VertexRemovalError("vertex " + std::to_string(v) + " cannot be deleted: no point found strictly inside the convex hull left");
  }

  // The faces of `fill` (cavity numbering) with no simplex on one side.
  static std::vector<std::pair<Key, int32_t>> open_faces(const Triangulation<D>& fill) {
    std::vector<std::pair<Key, int32_t>> faces;  // sorted key, and the side notation keeping `fill` inside
    for (uint32_t t = 0; t < fill.num_simplices(); ++t)
      for (int i = 0; i <= D; ++i)
        if (fill.neighbors[std::size_t{t} * (D + 1) + i] == kNone) {
          const Key f = facet_of(fill, t, i);
          faces.push_back({f, (D - i) % 2 == 0 ? -1 : 1});
        }
    return faces;
  }

  // The region the cavity's CDT covers when v is on the hull: the link faces it reached, the sheets'
  // simplices, and the new hull faces, notated with `fill` inside — for validate(). Every sheet
  // simplex (the last `sheet_faces` constraints of the cavity) must be a face of `fill`.
  Plc<D> closed_over_new_hull(uint32_t v, const Plc<D>& cavity, const Triangulation<D>& fill, std::size_t sheet_faces) const {
    std::unordered_map<Key, uint32_t, TupleHash> constraint;
    for (uint32_t j = 0; j < cavity.num_simplices(); ++j) {
      Key k;
      std::copy_n(cavity.simplex(j), D, k.begin());
      constraint.emplace(sorted(k), j);
    }
    std::unordered_map<Key, int, TupleHash> faces_of_fill;
    for (uint32_t t = 0; t < fill.num_simplices(); ++t)
      for (int i = 0; i <= D; ++i) {
        const Key f = facet_of(fill, t, i);
        ++faces_of_fill[sorted(f)];
      }
    Plc<D> region;
    region.points = cavity.points;
    for (std::size_t j = cavity.num_simplices() - sheet_faces; j < cavity.num_simplices(); ++j) {
      Key k;
      std::copy_n(cavity.simplex(j), D, k.begin());
      if (!faces_of_fill.count(sorted(k))) no_cdt(v, "a facet through it is not covered after the deletion", {});
      region.simplices.insert(region.simplices.end(), k.begin(), k.end());
      region.exterior.push_back(cavity.exterior_of(j));
    }
    for (const auto& [f, side] : open_faces(fill)) {
      const auto c = constraint.find(sorted(f));
      if (c != constraint.end() && c->second >= cavity.num_simplices() - sheet_faces) continue;  // added above
      region.simplices.insert(region.simplices.end(), f.begin(), f.end());
      region.exterior.push_back(side < 0 ? ExteriorSide::Negative : ExteriorSide::Positive);
    }
    return region;
  }

  // The new hull is convex: at every ridge of a new hull face, the hull face across (new, or old
  // outside the star) does not bend outward. A closed surface that is locally convex everywhere
  // bounds a convex set, and every point is a vertex inside it: it is the convex hull.
  void check_new_hull(uint32_t v, const std::vector<uint32_t>& star, const Triangulation<D>& fill, const std::vector<LinkFace>& link) const {
    struct HullFace {
      Key f;
      uint32_t inner;  // a vertex on its domain side
    };
    std::unordered_map<Key, const LinkFace*, TupleHash> link_of;
    for (const LinkFace& f : link) link_of.emplace(f.key, &f);
    std::vector<HullFace> hull;
    std::unordered_map<Key, bool, TupleHash> covered;
    for (uint32_t t = 0; t < fill.num_simplices(); ++t)
      for (int i = 0; i <= D; ++i) {
        const Key f = facet_of(fill, t, i);
        covered[sorted(f)] = true;
        if (fill.neighbors[std::size_t{t} * (D + 1) + i] == kNone && !link_of.count(sorted(f)) && !constraint_of.contains(sorted(f)))
          hull.push_back({f, fill.simplex(t)[i]});
      }
    for (const LinkFace& f : link)
      if (!covered.count(f.key) && f.across != kNone)  // the link face is a hull face now
        hull.push_back({f.key, simplex(f.across / (D + 1))[f.across % (D + 1)]});
    std::unordered_map<std::array<uint32_t, D - 1>, std::vector<uint32_t>, TupleHash> at_ridge;
    const auto ridge = [](const Key& f, int skip) {
      std::array<uint32_t, D - 1> r;
      for (int k = 0, j = 0; k < D; ++k)
        if (k != skip) r[j++] = f[k];
      std::sort(r.begin(), r.end());
      return r;
    };
    for (uint32_t h = 0; h < hull.size(); ++h)
      for (int k = 0; k < D; ++k) at_ridge[ridge(hull[h].f, k)].push_back(h);
    const auto side = [&](const Key& f, uint32_t x) {
      predicates::Coords<D + 1> c;
      for (int k = 0; k < D; ++k) c[k] = point(f[k]);
      c[D] = point(x);
      return predicates::orient<D>(c);
    };
    for (uint32_t h = 0; h < hull.size(); ++h)
      for (int k = 0; k < D; ++k) {
        const auto r = ridge(hull[h].f, k);
        const auto& on = at_ridge[r];
        uint32_t apex = kNone;
        if (on.size() == 2) {
          const Key& g = hull[on[0] == h ? on[1] : on[0]].f;
          for (uint32_t x : g)
            if (!std::binary_search(r.begin(), r.end(), x)) apex = x;
        } else if (on.size() == 1) {
          apex = old_hull_apex(r, star, link);
        }
        if (apex == kNone) no_cdt(v, "the convex hull left has no face across ridge " + detail::ids_text(r.data(), D - 1), {});
        const Sign inside = side(hull[h].f, hull[h].inner), there = side(hull[h].f, apex);
        if (there != Sign::Zero && there != inside) {
          std::vector<uint32_t> witness(hull[h].f.begin(), hull[h].f.end());
          witness.push_back(apex);
          no_cdt(v, "the domain left would not be convex at face " + detail::ids_text(hull[h].f.data(), D), witness);
        }
      }
  }

  // Every vertex of the link must stay a vertex: in a new simplex, or in one outside the star (a
  // point left outside the new hull would make it no convex hull of the points).
  void require_link_vertices_kept(uint32_t v, const std::vector<uint32_t>& ids, const Triangulation<D>& fill,
                                  const std::vector<LinkFace>& link) const {
    std::unordered_map<uint32_t, bool> kept;
    for (uint32_t x : fill.simplices) kept[x] = true;
    for (const LinkFace& f : link)
      if (f.across != kNone)
        for (uint32_t x : f.key) kept[x] = true;
    for (uint32_t x : ids)
      if (!kept.count(x)) no_cdt(v, "vertex " + std::to_string(x) + " would be left outside the new convex hull", {x});
  }

  // The rounded centroid of simplex sigma if it lies strictly inside it (exact test).
  std::optional<std::array<double, D>> centroid_strictly_inside(const std::array<uint32_t, D + 1>& sigma) const {
    const auto coords = [&](int replaced, const double* x) {
      predicates::Coords<D + 1> c;
      for (int k = 0; k <= D; ++k) c[k] = k == replaced ? x : point(sigma[k]);
      return c;
    };
    const Sign whole = predicates::orient<D>(coords(-1, nullptr));
    if (whole == Sign::Zero) return std::nullopt;
    std::array<double, D> centroid{};
    for (int k = 0; k < D; ++k) {
      double sum = 0;
      for (uint32_t x : sigma) sum += point(x)[k];
      centroid[k] = sum / (D + 1);
    }
    for (int k = 0; k <= D; ++k)
      if (predicates::orient<D>(coords(k, centroid.data())) != whole) return std::nullopt;
    return centroid;
  }

  // The old hull face at ridge r outside the star: walk around r from a link face's outside
  // neighbour until a facet without a neighbour; returns its vertex off r (kNone if none).
  uint32_t old_hull_apex(const std::array<uint32_t, D - 1>& r, const std::vector<uint32_t>& star, const std::vector<LinkFace>& link) const {
    const auto holds_r = [&](const Key& f) {
      return std::all_of(r.begin(), r.end(), [&](uint32_t x) { return std::count(f.begin(), f.end(), x) > 0; });
    };
    for (const LinkFace& f : link) {
      if (!holds_r(f.key)) continue;
      if (f.across == kNone) {  // an old hull face itself, kept
        for (uint32_t x : f.key)
          if (!std::count(r.begin(), r.end(), x)) return x;
      }
      uint32_t u = f.across / (D + 1), entered = f.across % (D + 1);
      for (std::size_t steps = 0; steps < live_simplices; ++steps) {
        int leave = -1;
        for (int i = 0; i <= D; ++i)
          if (i != static_cast<int>(entered) && !std::count(r.begin(), r.end(), simplex(u)[i])) leave = i;
        const uint32_t next = neighbors[std::size_t{u} * (D + 1) + leave];
        if (next == kNone) return simplex(u)[entered];
        u = next / (D + 1);
        entered = next % (D + 1);
        if (std::count(star.begin(), star.end(), u)) break;  // around r back into the cavity
      }
    }
    return kNone;
  }

  // Which side of constraint c (through v) is outside the cavity for the sweep: none when the star
  // has simplices on both sides (an inner facet), else the side without them.
  ExteriorSide cavity_side(const std::vector<uint32_t>& star, const Key& c) const {
    int sides = 0, last = 0;
    for (uint32_t t : star) {
      // c is a facet of t when t's vertex off c is its only one.
      int off = -1, count = 0;
      for (int i = 0; i <= D; ++i)
        if (std::find(c.begin(), c.end(), simplex(t)[i]) == c.end()) off = i, ++count;
      if (count != 1) continue;
      predicates::Coords<D + 1> p;
      for (int k = 0; k < D; ++k) p[k] = point(c[k]);
      p[D] = point(simplex(t)[off]);
      last = predicates::to_int(predicates::orient<D>(p));
      ++sides;
    }
    if (sides != 1) return ExteriorSide::None;
    return last > 0 ? ExteriorSide::Negative : ExteriorSide::Positive;
  }

  // Across every link face that is no constraint, the new simplex and the one outside must be
  // locally Delaunay (under the same perturbation): with the cavity's own CDT validated and the
  // rest unchanged, every facet of the whole is then locally constrained Delaunay — a CDT.
  void check_link_delaunay(uint32_t v, const Triangulation<D>& fill, const std::vector<LinkFace>& link, const Wiring& wiring) const {
    std::vector<uint32_t> inner_of(link.size(), kNone);  // link face -> the new simplex on it (the first)
    for (std::size_t k = wiring.link_face.size(); k-- > 0;)
      if (wiring.link_face[k] != kNone) inner_of[wiring.link_face[k]] = static_cast<uint32_t>(k / (D + 1));
    for (uint32_t j = 0; j < link.size(); ++j) {
      const LinkFace& face = link[j];
      if (face.across == kNone || constraint_of.contains(face.key)) continue;
      const uint32_t apex = simplex(face.across / (D + 1))[face.across % (D + 1)];
      const uint32_t t = inner_of[j];
      if (t == kNone) continue;  // no new simplex there: a hull face now (v was on the hull)
      predicates::Vertices<D + 1> s;
      for (int i = 0; i <= D; ++i) s[i] = vertex(fill.simplex(t)[i]);
      if (predicates::inside_circumsphere<D>(s, vertex(apex))) {
        std::vector<uint32_t> witness(fill.simplex(t), fill.simplex(t) + D + 1);
        witness.push_back(apex);
        no_cdt(v, "simplex " + detail::ids_text(fill.simplex(t), D + 1) + " of the cavity has vertex " + std::to_string(apex) +
                      " inside its circumsphere across face " + detail::ids_text(face.key.data(), D),
               witness);
      }
    }
  }

  // The plan's Wiring (above), from the new simplices (global ids, neighbours among themselves), the
  // link and the sheets' new constraints.
  Wiring wire(const Triangulation<D>& fill, const std::vector<LinkFace>& link, const std::vector<NewConstraint>& added) const {
    Wiring w;
    detail::SortedKeys<Key> link_of;  // link face key -> its index in `link`
    for (uint32_t j = 0; j < link.size(); ++j) link_of.add(link[j].key, j);
    link_of.sort();
    const std::size_t n = fill.num_simplices();
    w.link_face.assign(n * (D + 1), kNone);
    std::vector<char> covered(link.size(), 0);
    for (uint32_t t = 0; t < n; ++t)
      for (int i = 0; i <= D; ++i)
        if (fill.neighbors[std::size_t{t} * (D + 1) + i] == kNone)
          if (const uint32_t* j = link_of.find(sorted(facet_of(fill, t, i)))) w.link_face[std::size_t{t} * (D + 1) + i] = *j, covered[*j] = 1;
    for (uint32_t j = 0; j < link.size(); ++j)
      if (link[j].across != kNone && !covered[j]) w.uncovered.push_back(j);
    // With every link face covered, each of its vertices is in a new simplex: no walk changes.
    if (!w.uncovered.empty()) {
      std::vector<uint32_t> in_fill = fill.simplices;
      std::sort(in_fill.begin(), in_fill.end());
      for (uint32_t j = 0; j < link.size(); ++j) {
        if (link[j].across == kNone) continue;
        for (uint32_t x : link[j].key)
          if (!std::binary_search(in_fill.begin(), in_fill.end(), x)) w.outside_only.push_back({x, j});
      }
    }
    if (regions.empty()) return w;
    // A new simplex on the link takes the region of the star simplex it replaced there (the last
    // such face's); the others take their neighbours' across facets that are no constraints once
    // the deletion is applied. A facet between two new simplices lies inside the star, where every
    // face of the mesh has v: it is a constraint only as one of the sheets' new ones.
    w.region.assign(n, kRegionAsItIs);
    std::vector<uint32_t> queue;
    for (uint32_t t = 0; t < n; ++t) {
      bool on_link = false;
      for (int i = 0; i <= D; ++i)
        if (const uint32_t j = w.link_face[std::size_t{t} * (D + 1) + i]; j != kNone) w.region[t] = link[j].region, on_link = true;
      if (on_link) queue.push_back(t);
    }
    std::vector<Key> new_constraints;
    for (const NewConstraint& c : added) new_constraints.push_back(sorted(c.key));
    std::sort(new_constraints.begin(), new_constraints.end());
    std::vector<char> known(n, 0);
    for (const uint32_t t : queue) known[t] = 1;
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const uint32_t t = queue[k];
      for (int i = 0; i <= D; ++i) {
        const uint32_t inner = fill.neighbors[std::size_t{t} * (D + 1) + i];
        if (inner == kNone || known[inner / (D + 1)]) continue;
        if (!new_constraints.empty() && std::binary_search(new_constraints.begin(), new_constraints.end(), sorted(facet_of(fill, t, i))))
          continue;
        known[inner / (D + 1)] = 1;
        w.region[inner / (D + 1)] = w.region[t];
        queue.push_back(inner / (D + 1));
      }
    }
    return w;
  }

  uint32_t new_slot() {
    ++live_simplices;
    if (!free_slots.empty()) {
      const uint32_t t = free_slots.back();
      free_slots.pop_back();
      return t;
    }
    const uint32_t t = static_cast<uint32_t>(simplices.size() / (D + 1));
    changed_at.push_back(0);
    simplices.resize(simplices.size() + D + 1);
    neighbors.resize(neighbors.size() + D + 1);
    if (!regions.empty()) regions.push_back(0);
    return t;
  }

  void commit(const Plan& p) {
    const uint32_t stamp = ++commits;
    for (uint32_t t : p.star) {
      changed_at[t] = stamp;
      simplex(t)[0] = kNone;
      free_slots.push_back(t);
      --live_simplices;
    }
    alive[p.v] = 0;
    --live_vertices;
    simplex_at[p.v] = kNone;
    for (uint32_t c : p.through) {
      constraint_alive[c] = 0;
      constraint_of.erase(sorted(constraints[c]));
      for (uint32_t x : constraints[c]) std::erase(constraints_at[x], c);  // scanned by every plan near x
    }
    for (const NewConstraint& c : p.added) add_constraint(c.key, c.plc_side, c.tag);

    const Triangulation<D>& fill = p.fill;
    const Wiring& w = p.wiring;
    std::vector<uint32_t> slot(fill.num_simplices());
    for (auto& s : slot) s = new_slot();
    for (uint32_t t = 0; t < fill.num_simplices(); ++t) {
      const uint32_t g = slot[t];
      changed_at[g] = stamp;
      std::copy_n(fill.simplex(t), D + 1, simplex(g));
      for (int i = 0; i <= D; ++i) {
        simplex_at[simplex(g)[i]] = g;
        uint32_t& across = neighbors[std::size_t{g} * (D + 1) + i];
        const uint32_t inner = fill.neighbors[std::size_t{t} * (D + 1) + i];
        if (inner != kNone) {
          across = slot[inner / (D + 1)] * (D + 1) + inner % (D + 1);
          continue;
        }
        const uint32_t j = w.link_face[std::size_t{t} * (D + 1) + i];
        across = j == kNone ? kNone : p.link[j].across;  // kNone: a sheet's new simplex on the domain's boundary
        if (across != kNone) neighbors[across] = g * (D + 1) + i, changed_at[across / (D + 1)] = stamp;
      }
      if (!regions.empty() && w.region[t] != kRegionAsItIs) regions[g] = w.region[t];
    }
    // Link faces no new simplex reached (v was on the hull): their outside simplex is on the hull now.
    for (const uint32_t j : w.uncovered) neighbors[p.link[j].across] = kNone, changed_at[p.link[j].across / (D + 1)] = stamp;
    for (const auto& [x, j] : w.outside_only) simplex_at[x] = p.link[j].across / (D + 1);
  }

  Plc<D> plc_without(uint32_t v) const {
    require_vertex(v);
    const std::vector<uint32_t> through = live_constraints_at(v);
    std::vector<uint32_t> renumber(alive.size(), kNone);
    Plc<D> plc;
    for (uint32_t x = 0; x < alive.size(); ++x)
      if (alive[x] && x != v) {
        renumber[x] = static_cast<uint32_t>(plc.num_points());
        plc.points.insert(plc.points.end(), point(x), point(x) + D);
      }
    plc.region_seeds = region_seeds;
    const auto add = [&](const Key& c, ExteriorSide side, uint32_t tag) {
      for (uint32_t x : c) plc.simplices.push_back(renumber[x]);
      plc.exterior.push_back(side);
      plc.tags.push_back(tag);
    };
    for (uint32_t c = 0; c < constraints.size(); ++c)
      if (constraint_alive[c] && !std::count(through.begin(), through.end(), c))
        add(constraints[c], c < exterior.size() ? exterior[c] : ExteriorSide::None, tags[c]);
    const auto sheets = sheets_through(v, through);
    if (const std::string why = star_too_large_to_unbend(v, sheets, star_of(v).size()); !why.empty()) throw VertexRemovalError(why);
    for (const auto& sheet : sheets) {
      const uint32_t c0 = through[sheet.constraints.front()];
      for (const Key& s : sheet.fill) add(s, c0 < exterior.size() ? exterior[c0] : ExteriorSide::None, tags[c0]);
    }
    if (exterior.empty()) plc.exterior.clear();
    if (!has_tags) plc.tags.clear();
    return plc;
  }

  // What a snapshot is made of: the vertices, simplices and constraints, dead ones included.
  struct Parts {
    std::vector<double> points;
    uint32_t num_input_points;
    std::vector<uint32_t> steiner_on, rank;
    std::vector<char> alive;
    std::vector<uint32_t> simplices, neighbors;
    std::vector<int32_t> regions;
    std::vector<std::array<uint32_t, D>> constraints;
    std::vector<char> constraint_alive;
    std::vector<ExteriorSide> exterior;
    std::vector<uint32_t> tags;
    bool has_tags;
    std::vector<RegionSeed<D>> region_seeds;
  };
  Snapshot snapshot() const {
    return assemble(Parts{points, num_input_points, steiner_on, rank, alive, simplices, neighbors, regions, constraints,
                          constraint_alive, exterior, tags, has_tags, region_seeds});
  }
  // The mesh's own arrays become the snapshot's, compacted where they are, and the rest is freed
  // first: the snapshot of a large mesh costs no second copy of it (the fine perforated tube's 9M
  // tetrahedra: 465 MB at the end of the deletion pass).
  Snapshot release() {
    simplex_at = {}, free_slots = {}, constraints_at = {}, constraint_of = detail::TupleMap<D>(0), changed_at = {};
    return assemble(Parts{std::move(points), num_input_points, std::move(steiner_on), std::move(rank), std::move(alive),
                          std::move(simplices), std::move(neighbors), std::move(regions), std::move(constraints),
                          std::move(constraint_alive), std::move(exterior), std::move(tags), has_tags, std::move(region_seeds)});
  }
  // The live vertices numbered anew in the same order (so the perturbation order, tri's
  // perturbation_rank, stays the same), the live simplices and constraints in slot order. Each array
  // is compacted in place: an element only moves to a lower index.
  static Snapshot assemble(Parts parts) {
    Snapshot out;
    Triangulation<D>& tri = out.triangulation;
    std::vector<uint32_t> renumber(parts.alive.size(), kNone);
    for (uint32_t x = 0; x < parts.alive.size(); ++x) {
      if (!parts.alive[x]) continue;
      const uint32_t y = renumber[x] = static_cast<uint32_t>(out.old_ids.size());
      out.old_ids.push_back(x);
      std::copy_n(parts.points.data() + std::size_t{x} * D, D, parts.points.data() + std::size_t{y} * D);
      if (x < parts.num_input_points) ++tri.num_input_points;
      else parts.steiner_on[y - tri.num_input_points] = parts.steiner_on[x - parts.num_input_points];
    }
    parts.alive = {};
    parts.points.resize(out.old_ids.size() * D);
    parts.steiner_on.resize(out.old_ids.size() - tri.num_input_points);
    tri.points = std::move(parts.points);
    tri.steiner_on = std::move(parts.steiner_on);
    if (!parts.rank.empty()) {  // the same order among the vertices left, as ranks 0..n-1
      std::vector<uint32_t> by_rank = out.old_ids;
      std::sort(by_rank.begin(), by_rank.end(), [&](uint32_t a, uint32_t b) { return parts.rank[a] < parts.rank[b]; });
      tri.perturbation_rank.resize(by_rank.size());
      for (uint32_t r = 0; r < by_rank.size(); ++r) tri.perturbation_rank[renumber[by_rank[r]]] = r;
    }
    const std::size_t slots = parts.simplices.size() / (D + 1);
    std::vector<uint32_t> compact(slots, kNone);
    uint32_t count = 0;
    for (uint32_t t = 0; t < slots; ++t)
      if (parts.simplices[std::size_t{t} * (D + 1)] != kNone) compact[t] = count++;
    for (uint32_t t = 0; t < slots; ++t) {
      if (compact[t] == kNone) continue;
      const std::size_t from = std::size_t{t} * (D + 1), to = std::size_t{compact[t]} * (D + 1);
      for (int i = 0; i <= D; ++i) {
        parts.simplices[to + i] = renumber[parts.simplices[from + i]];
        const uint32_t across = parts.neighbors[from + i];
        parts.neighbors[to + i] = across == kNone ? kNone : compact[across / (D + 1)] * (D + 1) + across % (D + 1);
      }
      if (!parts.regions.empty()) parts.regions[compact[t]] = parts.regions[t];
    }
    parts.simplices.resize(std::size_t{count} * (D + 1));
    parts.neighbors.resize(std::size_t{count} * (D + 1));
    if (!parts.regions.empty()) parts.regions.resize(count);
    tri.simplices = std::move(parts.simplices);
    tri.neighbors = std::move(parts.neighbors);
    tri.regions = std::move(parts.regions);
    Plc<D>& plc = out.plc;
    plc.points = tri.points;
    plc.region_seeds = std::move(parts.region_seeds);
    plc.simplices.reserve(std::count(parts.constraint_alive.begin(), parts.constraint_alive.end(), 1) * std::size_t{D});
    for (uint32_t c = 0; c < parts.constraints.size(); ++c) {
      if (!parts.constraint_alive[c]) continue;
      for (uint32_t x : parts.constraints[c]) plc.simplices.push_back(renumber[x]);
      if (!parts.exterior.empty()) plc.exterior.push_back(c < parts.exterior.size() ? parts.exterior[c] : ExteriorSide::None);
      if (parts.has_tags) plc.tags.push_back(parts.tags[c]);
    }
    return out;
  }
};

template <int D>
EditableCdt<D>::EditableCdt(Plc<D> plc, Triangulation<D> tri) {
  if (tri.neighbors.size() != tri.simplices.size()) compute_neighbors(tri);
  impl_ = std::make_unique<Impl>(std::move(plc), std::move(tri));
}

template <int D>
EditableCdt<D>::EditableCdt(EditableCdt&&) noexcept = default;
template <int D>
EditableCdt<D>& EditableCdt<D>::operator=(EditableCdt&&) noexcept = default;
template <int D>
EditableCdt<D>::~EditableCdt() = default;

template <int D>
std::vector<uint32_t> EditableCdt<D>::remove_vertex(uint32_t v) {
  return impl_->remove_vertex(v);
}
template <int D>
struct EditableCdt<D>::Removal::Plan : Impl::Plan {};
template <int D>
EditableCdt<D>::Removal::Removal() = default;
template <int D>
EditableCdt<D>::Removal::Removal(Removal&&) noexcept = default;
template <int D>
typename EditableCdt<D>::Removal& EditableCdt<D>::Removal::operator=(Removal&&) noexcept = default;
template <int D>
EditableCdt<D>::Removal::~Removal() = default;

template <int D>
typename EditableCdt<D>::Removal EditableCdt<D>::plan_removal(uint32_t v) const {
  Removal r;
  r.plan_ = std::make_unique<typename Removal::Plan>();
  static_cast<typename Impl::Plan&>(*r.plan_) = impl_->plan(v);
  return r;
}
template <int D>
std::unique_ptr<typename EditableCdt<D>::Removal::Plan> EditableCdt<D>::take(Removal& removal) {
  if (!removal.plan_) throw std::invalid_argument("EditableCdt: committing an empty Removal (moved from, or committed already)");
  return std::move(removal.plan_);
}
template <int D>
std::vector<uint32_t> EditableCdt<D>::commit_removal(Removal&& removal) {
  std::vector<uint32_t> neighbours;
  impl_->apply(std::move(*take(removal)), neighbours, true);
  return neighbours;
}
template <int D>
bool EditableCdt<D>::try_commit_removal(Removal&& removal, std::vector<uint32_t>& neighbours, std::vector<uint32_t>* witness) {
  return impl_->apply(std::move(*take(removal)), neighbours, false, witness);
}
template <int D>
bool EditableCdt<D>::plan_is_current(const Removal& removal) const {
  return removal.plan_ && !impl_->stale(*removal.plan_);
}
template <int D>
uint64_t EditableCdt<D>::plans_redone() const {
  return impl_->redone;
}
template <int D>
uint64_t EditableCdt<D>::refused_early() const {
  return impl_->refused_early;
}
template <int D>
bool EditableCdt<D>::has_vertex(uint32_t v) const {
  return v < impl_->alive.size() && impl_->alive[v];
}
template <int D>
void EditableCdt<D>::unbend_facets_at_steiner_points(std::size_t largest_star) {
  impl_->unbend = largest_star > 0;
  impl_->unbend_largest_star = largest_star;
}

template <int D>
void EditableCdt<D>::know_flat_facets(std::vector<char> flat_by_tag) {
  impl_->flat_by_tag = std::move(flat_by_tag);
}

template <int D>
void EditableCdt<D>::guess_blocked_refusals(bool on) {
  impl_->guess_blocked_refusals = on;
}

template <int D>
void EditableCdt<D>::limit_growth(unsigned factor) {
  impl_->growth_factor = factor;
}

template <int D>
std::vector<uint32_t> EditableCdt<D>::neighbours(uint32_t v) const {
  impl_->require_vertex(v);
  std::vector<uint32_t> link;
  for (uint32_t t : impl_->star_of(v))
    for (int i = 0; i <= D; ++i)
      if (impl_->simplex(t)[i] != v) link.push_back(impl_->simplex(t)[i]);
  std::sort(link.begin(), link.end());
  link.erase(std::unique(link.begin(), link.end()), link.end());
  return link;
}
template <int D>
std::vector<uint32_t> EditableCdt<D>::constraint_neighbours(uint32_t v) const {
  impl_->require_vertex(v);
  std::vector<uint32_t> around;
  for (uint32_t c : impl_->live_constraints_at(v))
    for (uint32_t w : impl_->constraints[c])
      if (w != v) around.push_back(w);
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  return around;
}
template <int D>
std::size_t EditableCdt<D>::num_vertices() const {
  return impl_->live_vertices;
}
template <int D>
std::size_t EditableCdt<D>::num_simplices() const {
  return impl_->live_simplices;
}
template <int D>
Plc<D> EditableCdt<D>::plc_without(uint32_t v) const {
  return impl_->plc_without(v);
}
template <int D>
typename EditableCdt<D>::Snapshot EditableCdt<D>::snapshot() const {
  return impl_->snapshot();
}
template <int D>
typename EditableCdt<D>::Snapshot EditableCdt<D>::release() && {
  Snapshot out = impl_->release();
  impl_.reset();
  return out;
}

template class EditableCdt<2>;
template class EditableCdt<3>;
template class EditableCdt<4>;
template class EditableCdt<5>;

}  // namespace sweepcdt
