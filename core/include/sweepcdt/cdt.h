// cdt(): the constrained Delaunay triangulation of a PLC — sweepcdt's library entry point.
//
//   Plc<3> plc = ...;                       // points, constraining triangles, exterior notations
//   Triangulation<3> tri = cdt(plc);        // throws PlcError, NoCdtError or CancelledError
//
// Every simplex of the result is constrained Delaunay for the points under the lifting-map
// perturbation of paper §6 (so degenerate, cospherical inputs get a well-defined answer), every
// constraining simplex is a facet, and the simplices cover exactly the triangulation domain: the
// convex hull without exterior notations, the facet-bounded domain with them.
//
// The perturbation is ordered by vertex id — unless that order leaves the perturbed PLC without a
// CDT while a later order of sweepcdt/perturbation_order.h gives one: paper §6 warns that "the order
// in which the vertices are perturbed can determine whether or not a triangulation is discovered"
// (an exactly cospherical cube whose face diagonals allow one tetrahedralization only). The result
// then records its order in Triangulation::perturbation_rank, and validate() checks it under that.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sweepcdt/error.h"
#include "sweepcdt/perturbation_order.h"
#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"
#include "sweepcdt/validate.h"

namespace sweepcdt {

enum class Algorithm {
  SweepSphere,  // paper §3: SWEEPCDT with an expanding sphere; any domain
  SweepPlane,   // paper §3: SWEEPCDT with a sweep plane; facet-bounded domains (a convex hull
                // domain is swept with the sphere instead, and the statistics say so)
  GiftWrap,     // paper §2: O(n_v n_f n_s); the reference the sweeps are tested against
  CavitySweep,  // the default, any D: the Delaunay triangulation, its simplices that a constraint
                // meets other than in a common face triangulated again by the sweep sphere, cavity
                // by cavity (core/src/cavity/cavity_cdt.h); the whole PLC swept with the sphere when
                // that cannot decide
};

const char* to_string(Algorithm algorithm);

// Every algorithm, the default first: the order of the hosts' and the command line's lists.
inline constexpr Algorithm kAlgorithms[] = {Algorithm::CavitySweep, Algorithm::SweepSphere, Algorithm::SweepPlane,
                                            Algorithm::GiftWrap};
// The algorithm to_string() names ("gift-wrap" too), or none.
std::optional<Algorithm> algorithm_named(std::string_view name);
// "cavity-sweep, sweep-sphere, sweep-plane or giftwrap": for messages.
std::string algorithm_choices();

// What a run did, for callers who want to know (CLI --stats, benchmarks).
struct CdtStatistics {
  Algorithm algorithm = Algorithm::CavitySweep;  // the one that actually ran
  uint64_t simplices = 0;
  // The sweeps' counters. Of the cavity sweep's, only when every cavity was swept (after one finds no
  // CDT the others stop, as far as the threads got; the whole PLC's sweep counts instead).
  uint64_t queue_pushes = 0, queue_pops = 0, stale_pops = 0;  // sweeps: priority-queue operations
  uint64_t drop_moves = 0;  // sweeps: vertices moved between drop lists, the paper's sum of drop(f)
  // CavitySweep: constraints that are no face of the Delaunay tetrahedralization, and its tetrahedra
  // triangulated again in cavities (those they disturb and those enclosed by them).
  uint64_t missing_constraints = 0, cavity_tetrahedra = 0;
  uint64_t steiner_points = 0, steiner_rounds = 0;  // the points the result has; refinement rounds (each ends with the facets' flips)
  // Refinements run: lazy ones (cdt.cpp: segments required where a cavity finds no CDT) and, when
  // they do not end in a CDT, one of every segment, leaving the folds that rounding made as they are,
  // then, when that has no CDT either, one making them Delaunay too; 0 without Steiner points or
  // coplanar facets.
  uint64_t steiner_attempts = 0;
  uint64_t steiner_points_removed = 0;  // added by refinement, then deleted again (remove_steiner_points)
  // The deletion pass: deletions worked out (each a star CDT), and retries of refused points skipped
  // because no vertex of their refusal's witness, nor of a constraint through them, went since
  // (core/src/edit/remove_steiner.cpp); of those tried, the ones refused before their star CDT: the
  // segment they would leave is not Delaunay (core/src/edit/blocked_segment.h), or the point is
  // rounded off its segment and its star too large to unbend.
  uint64_t steiner_deletions_tried = 0, steiner_retries_skipped = 0, steiner_refused_early = 0;
  uint64_t facets = 0, facet_flips = 0;  // D = 3 with Steiner points or coplanar facets: facets, and the
                                         // edge flips that gave each its 2D CDT
  // Paper §6: runs made, one per perturbation order tried (1 unless the vertex-id order found no CDT
  // after exact ties), and the order of the result (0 = vertex ids; sweepcdt/perturbation_order.h).
  // The times and the sweep counters add up all runs; the Steiner and facet counts and `simplices`
  // are those of the run returned.
  uint32_t perturbation_orders = 0, perturbation_order = 0;
  double seconds_check = 0, seconds_setup = 0, seconds_build = 0, seconds_finish = 0;
  // The PLC carried a record of an earlier check that covers it (Plc::checked, e.g. from an importer):
  // the geometric checks were not repeated, only the O(n + m) ones.
  bool check_recorded = false;
  // D = 3: the Delaunay tetrahedralization of the points was the one the importer computed beside
  // its check (sweepcdt::find_problems_before_cdt), not computed again.
  bool tetrahedralization_recorded = false;
};

struct Progress {
  const char* phase;  // e.g. "gift-wrapping"
  uint64_t done;      // vertices reached so far
  uint64_t total;     // vertices in all (0 when unknown)
};

// Steiner points (beyond the paper): most real surfaces have no CDT as given. Guarantees by dimension:
//   D = 2: every PLC has a CDT (segments are always recoverable), so Auto never adds a point.
//   D = 3: Auto splits the segments (edges of the input facets) that are not Delaunay — with the
//          concentric-shell rule that protects small input angles — until every segment is an edge of
//          the (perturbed) Delaunay triangulation of all points; each facet is then re-triangulated by
//          its own 2D CDT. Steiner points are the rounded results of a few floating-point operations
//          (sweepcdt/steiner_point.h): they lie on their segments to within a few units of rounding,
//          and the facet edges from them are slight folds; folds that are not Delaunay are split too
//          (a few points inside facets), so Shewchuk's CDT theorem holds for the refined PLC exactly
//          as computed. Limits (points, rounds) make a hopeless input fail with NoCdtError instead of
//          running away. core/src/steiner/refine.h has the details.
//   D >= 4: not implemented; Auto behaves as None (NoCdtError when no CDT exists).
//
// With the PLC as given (None, and Auto for D >= 4) a run that finds no CDT is retried under the
// next perturbation orders of sweepcdt/perturbation_order.h (up to kPerturbationOrders runs), but
// only while the failed runs met an exact tie of D+2 cospherical points — in an insphere test, or in
// the sweep keys of two simplices on one sphere (the sweep plane can find "no CDT" from those
// alone). A run that decided every such test without the perturbation is taken to end the same
// under any order: NoCdtError after one run (Schönhardt's twisted prism). A PLC with ties but no
// CDT costs up to kPerturbationOrders runs.
// What this does not promise: that a PLC with a CDT gets one. Only triangulations that some order
// produces can be found (for a cospherical group, those that pull its first vertex: join it to all
// it sees), only kPerturbationOrders fixed orders are tried — several groups that each need the
// right vertex first are all served by one order only with luck — and paper §6 leaves open whether
// some order always works. NoCdtError reports the vertex-id run's witness and says how many orders
// were tried.
enum class SteinerMode {
  None,  // the PLC as given: NoCdtError when it has no CDT (paper §2) under any order tried (above)
  Auto,  // split segments until a CDT exists (see above); perturbed by vertex id only
};

// What the constraining simplices of a D = 3 PLC stand for.
enum class FacetMode {
  Triangles,  // each triangle is a facet of its own: every triangle edge is a segment
  Coplanar,   // edge-adjacent, exactly coplanar triangles with the same exterior side form one polygonal
              // facet, triangulated anew by its 2D CDT (paper §1: constraining simplices come from the
              // CDT of each facet); only facet boundaries are segments, so fewer Steiner points
};

struct Options {
  Algorithm algorithm = Algorithm::CavitySweep;
  SteinerMode steiner = SteinerMode::None;
  FacetMode facets = FacetMode::Triangles;
  // With Steiner points: delete each again, last added first, when the PLC left still has a CDT
  // (paper §5 vertex deletion, checked exactly; core/src/edit/remove_steiner.h). Refinement splits
  // every segment that is not Delaunay, far more than a CDT needs.
  bool remove_steiner_points = true;
  CdtStatistics* statistics = nullptr;  // filled in when set
  // Threads for the work that runs in parallel — the PLC check's intersection tests, validate()'s
  // per-simplex and per-facet tests, and (CavitySweep) the Delaunay tetrahedralization beside the
  // check — 0: every hardware thread. The result is the same for any number.
  unsigned threads = 0;
  // Called now and then; return false to cancel (cdt() then throws CancelledError).
  std::function<bool(const Progress&)> progress;
};

// The defaults of the surface converter — `sweepcdt mesh`, the Python module's tetrahedralize(),
// the FreeCAD and MeshLab plugins — where Options{} keeps the PLC exactly as given: Steiner points
// where the surface has no CDT as given, and exactly coplanar neighbouring triangles merged into one
// facet. Coplanar facets are the default because CAD tessellations fan long thin triangles across
// flat faces: kept as facets of their own, each of their edges must be made Delaunay, which takes
// orders of magnitude more Steiner points (issue 13; README, Steiner points). Faces flat only up to
// rounding stay as they are (never snapped unless asked: --snap) and get Steiner points instead.
inline Options mesh_defaults() {
  Options options;
  options.steiner = SteinerMode::Auto;
  options.facets = FacetMode::Coplanar;
  return options;
}

// The PLC has no CDT (paper §2: a face that cannot be finished, or a simplex that is not
// constrained Delaunay). `witness` holds the vertex ids of the face or simplex concerned.
class NoCdtError : public Error {
 public:
  NoCdtError(const std::string& what, std::vector<uint32_t> witness) : Error(what), witness_(std::move(witness)) {}
  const std::vector<uint32_t>& witness() const { return witness_; }

 private:
  std::vector<uint32_t> witness_;
};

class CancelledError : public Error {
 public:
  CancelledError() : Error("cancelled") {}
};

template <int D>
Triangulation<D> cdt(const Plc<D>& plc, const Options& options = {});

// The same, also returning the PLC actually triangulated: with Steiner points, the input's points
// and the Steiner points, and the input's triangles split at them (tags = input triangle index or
// input tag). validate_triangulated() checks a result against it exactly.
template <int D>
Triangulation<D> cdt(const Plc<D>& plc, const Options& options, Plc<D>* triangulated);

// validate() of a cdt() result against the PLC it actually triangulated (see above), which holds
// the Steiner points as its own points.
template <int D>
ValidationReport validate_triangulated(Triangulation<D> result, const Plc<D>& triangulated,
                                       ValidationLevel level = ValidationLevel::Full) {
  result.num_input_points = static_cast<uint32_t>(triangulated.num_points());
  result.steiner_on.clear();
  return validate(result, triangulated, level);
}

}  // namespace sweepcdt
