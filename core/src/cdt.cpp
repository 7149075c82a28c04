// cdt(): check the PLC, run the chosen algorithm, pair neighbours, assign regions — and verify the
// result before returning it: a PLC without a CDT must fail with NoCdtError, never return a wrong
// triangulation.
#include "sweepcdt/cdt.h"
#include "sweepcdt/star_cdt.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cavity/cavity_cdt.h"
#include "delaunay/in_background.h"
#include "delaunay/kept_tetrahedralization.h"
#include "parallel.h"
#include "gift_wrap.h"
#include "regions.h"
#include "relabel.h"
#include "edit/remove_steiner.h"
#include "refined_check.h"
#include "steiner/facet_groups.h"
#include "steiner/refine.h"
#include "sweep/sweep_cdt.h"
#include "sweepcdt/perturbation_order.h"
#include "sweepcdt/predicates/stats.h"
#include "sweepcdt/validate.h"

namespace sweepcdt {

const char* to_string(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::SweepSphere: return "sweep-sphere";
    case Algorithm::SweepPlane: return "sweep-plane";
    case Algorithm::GiftWrap: return "giftwrap";
    case Algorithm::CavitySweep: return "cavity-sweep";
  }
  return "unknown";
}

std::optional<Algorithm> algorithm_named(std::string_view name) {
  for (const Algorithm a : kAlgorithms)
    if (name == to_string(a)) return a;
  if (name == "gift-wrap") return Algorithm::GiftWrap;
  return std::nullopt;
}

std::string algorithm_choices() {
  std::string text;
  for (std::size_t i = 0; i < std::size(kAlgorithms); ++i)
    text += std::string(i == 0 ? "" : i + 1 == std::size(kAlgorithms) ? " or " : ", ") + to_string(kAlgorithms[i]);
  return text;
}

namespace {

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// The whole PLC by one of the paper's algorithms.
template <int D>
Triangulation<D> build(const Plc<D>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock) {
  // The sweep plane needs the domain's left boundary: it has it for facet-bounded domains only.
  stats.algorithm = options.algorithm;
  if ((options.algorithm == Algorithm::SweepPlane && !plc.facet_bounded()) || options.algorithm == Algorithm::CavitySweep)
    stats.algorithm = Algorithm::SweepSphere;
  switch (stats.algorithm) {
    case Algorithm::GiftWrap:
      return detail::gift_wrap(plc, options);
    case Algorithm::SweepPlane:
      return detail::sweep_cdt<D>(plc, std::nullopt, options, stats);
    case Algorithm::CavitySweep:  // not reached: stats.algorithm is the sphere then
    case Algorithm::SweepSphere: {
      const auto delta = detail::seed_simplex(plc);
      stats.seconds_setup += clock.lap();
      return detail::sweep_cdt<D>(plc, delta, options, stats);
    }
  }
  return {};
}


// Pairs the neighbours of the simplices `build` made of `plc` (unless it did), assigns regions, and
// verifies them — validate() checks the neighbours too.
template <int D>
Triangulation<D> finish(Triangulation<D> tri, const Plc<D>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock) {
  stats.seconds_build += clock.lap();
  stats.simplices = tri.num_simplices();
  if (tri.neighbors.empty()) compute_neighbors(tri);
  detail::assign_regions(tri, plc, options.threads);
  const ValidationReport report = validate(tri, plc, ValidationLevel::Full, options.threads);
  stats.seconds_finish += clock.lap();
  if (!report.ok())
    throw NoCdtError("no CDT: the constructed triangulation fails validation (" + report.failures.front().check + ": " +
                         report.failures.front().detail + ")",
                     {});
  return tri;
}

// Triangulates `plc` (already checked) and verifies the result. CavitySweep sweeps the whole PLC with
// the sphere when its own path cannot decide (cavity/cavity_cdt.h), or when its result fails
// validation — which happens only when the PLC has no CDT: a cavity can have a CDT while the whole
// does not; the whole sweep then fails too, with its witness.
// `delaunay`: the Delaunay tetrahedralization of plc's points, when refinement or cdt() computed it.
template <int D>
Triangulation<D> triangulate(const Plc<D>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock,
                             const detail::DelaunayMesh* delaunay = nullptr) {
  if (options.algorithm == Algorithm::CavitySweep) {
    stats.algorithm = Algorithm::CavitySweep;
    if (std::optional<Triangulation<D>> tri = detail::cavity_cdt<D>(plc, options, stats, delaunay)) {
      try {
        return finish(std::move(*tri), plc, options, stats, clock);
      } catch (const NoCdtError&) {
        // swept whole below
      }
    }
  }
  return finish(build(plc, options, stats, clock), plc, options, stats, clock);
}

// Refinement's figures into the statistics; the refined PLC tagged with the input facet each
// triangle is a piece of while Steiner points are deleted (remove_steiner.h: pieces of one input
// facet around a point form one sheet; run() puts the input's own tags back), and checked again where
// rounding may have changed it. Rounding a split point can, rarely, put it on another facet (two
// within rounding of each other): the input was valid, so that is no input error but a failure to
// find Steiner points. Without Steiner points nothing was rounded: each facet was only
// re-triangulated by flips in its own exact plane, which keeps it the same polygon, so the checked
// input stands for it. With them, so does every facet whose points lie exactly on it: only the
// others are tested again (refined_check.h).
void take_refined(detail::RefinedPlc& refined, const Options& options, CdtStatistics& stats, Stopwatch& clock) {
  stats.steiner_points = refined.steiner_on.size();
  stats.steiner_rounds = refined.rounds;
  stats.facets = refined.facets;
  stats.facet_flips = refined.flips;
  stats.tetrahedralization_recorded = stats.tetrahedralization_recorded || refined.tetrahedralization_recorded;
  refined.plc.tags = refined.original;
  try {
    if (!refined.steiner_on.empty()) detail::check_refined(refined.plc, refined.off_input, options.threads);
  } catch (const PlcError& e) {
    throw NoCdtError("Steiner points: rounding broke the refined PLC (" + e.problems().front().message +
                         ", in the refined PLC's numbering): two facets lie within rounding of each other there",
                     {});
  }
  stats.seconds_setup += clock.lap();
}

// The refined PLC by the cavity sweep alone (cavity/cavity_cdt.h), validated; nullopt, with the edges
// of the cavities that find no CDT in `failed_edges`, when one does not (or the whole fails
// validation: then it has no CDT either).
std::optional<Triangulation<3>> sweep_cavities(const detail::RefinedPlc& refined, const Options& options, CdtStatistics& stats,
                                               Stopwatch& clock, std::vector<std::array<uint32_t, 2>>* failed_edges,
                                               const std::function<void()>& all_swept = {}) {
  stats.algorithm = Algorithm::CavitySweep;
  std::optional<Triangulation<3>> tri =
      detail::cavity_cdt<3>(refined.plc, options, stats, refined.delaunay ? &*refined.delaunay : nullptr, failed_edges, all_swept);
  if (!tri) return std::nullopt;
  try {
    return finish(std::move(*tri), refined.plc, options, stats, clock);
  } catch (const NoCdtError&) {
    return std::nullopt;
  }
}

// Lazy Steiner refinement (issue 13; the cavity sweep only). Splitting every segment until it is
// Delaunay (the CDT theorem's premise) is far more than a CDT of the domain needs: a vertex that
// encroaches on a segment from outside the domain, or across a face flat up to rounding, often leaves
// the CDT intact. So the refinement first requires no segment at all, and the cavity sweep
// (cavity/cavity_cdt.h) tries the PLC as it is; the input segments of the cavities that find no CDT
// are required from then on, and the refinement goes on with them (from the second attempt with
// points on splitting, too, any segment that its points make not Delaunay where it was; the first
// leaves those to the cavity sweep: steiner/refine.cpp, Refiner::splits). A cavity without a CDT has a
// segment that is not Delaunay (the theorem, applied to the cavity's PLC: every other ridge of it is
// an edge of the Delaunay triangulation), or a fold that is not (folds are left as they are here:
// refine_every_segment says why; float points rarely make any), so each attempt requires segments
// not required before or stops. Returns the validated CDT with its refined PLC, or nullopt when the
// attempts run out, refinement fails (a limit, or a refined PLC fails its check), or the cavities
// all have a CDT that the whole does not: then the caller refines every segment.
//
// Only on surfaces with float coordinates (STL, glTF, Draco, most PLY), where a Steiner point lies
// exactly on its segment: where points are rounded off their segments, the folds they make and the
// points made from pieces' ends left the deletion pass with more points than after refining every
// segment (measured in session 20: more on 10 of 23 surfaces with double coordinates, up to 2.5x,
// fewer on 9; on float surfaces fewer on 18 of 66 and 11 more on one, 10% less time in all).
// Each attempt continues the last one's refinement (detail::Refinement): the first adds no point, the
// second starts from its Delaunay tetrahedralization of the input points, a third splits only the
// pieces of the segments required since (thingi: 0.33 s of 1.44 s was refining again from scratch).
// Between attempts the refinement keeps little (refine.h), but after the first the input's
// tetrahedralization: it is freed as soon as every cavity has a CDT (kept through the rest, assembly
// and validation, it raised the peak memory of a 327k-triangle float sphere by 14%).
constexpr int kLazyAttempts = 6;

bool all_float(const std::vector<double>& points) {
  return std::all_of(points.begin(), points.end(), [](double x) { return static_cast<double>(static_cast<float>(x)) == x; });
}

std::optional<Triangulation<3>> refine_lazily(const Plc<3>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock,
                                              detail::RefinedPlc& refined) {
  detail::RequiredSegments required;
  auto refinement = std::make_unique<detail::Refinement>(plc, options, required);
  for (int attempt = 0; attempt < kLazyAttempts && refinement; ++attempt) {
    ++stats.steiner_attempts;
    try {
      refined = refinement->next(std::move(refined));  // the last attempt's points and triangles taken back
      take_refined(refined, options, stats, clock);
    } catch (const NoCdtError&) {
      return std::nullopt;  // a limit, or rounding: refining every segment says so again, or succeeds
    }
    std::vector<std::array<uint32_t, 2>> failed_edges;
    if (std::optional<Triangulation<3>> tri = sweep_cavities(refined, options, stats, clock, &failed_edges, [&] { refinement.reset(); }))
      return tri;
    const std::size_t before = required.size();
    const uint32_t n = refined.num_input_points;
    for (const auto& [a, b] : failed_edges) {
      if (a < n && b < n) required.insert(detail::edge_key(a, b));  // an input segment, or no segment at all
      for (const uint32_t v : {a, b})
        if (v >= n && refined.on_segment[v - n][0] != kNone) required.insert(detail::edge_key(refined.on_segment[v - n][0], refined.on_segment[v - n][1]));
    }
    if (required.size() == before) return std::nullopt;
  }
  return std::nullopt;
}

// Every segment refined, first with the folds left as they are. A split point rounded off its
// segment (double coordinates: ASCII STL, OBJ, OFF) bends the facets at the edges from it, and the
// CDT theorem's premise wants those folds Delaunay too; but the CDT often does without: on an
// OpenSCAD thread exported as ASCII STL, 20869 folds were not Delaunay after the segments' 59546
// points, making them so took 9 more rounds and 91270 points (the deletion pass then removed 126813
// of the 150816, in 21 s), and the cavity sweep found the CDT of the PLC without them (8 s, 21903
// points kept). The algorithm decides exactly — the cavity sweep by its cavities alone (one without
// a CDT means the whole has none), the others by sweeping — and when it finds no CDT the folds are
// made Delaunay after all: nullopt, with `refined` refined again, which the caller triangulates (as
// it does when no fold was left, the theorem's premise holding already).
std::optional<Triangulation<3>> refine_every_segment(const Plc<3>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock,
                                                     detail::RefinedPlc& refined) {
  ++stats.steiner_attempts;
  refined = detail::refine(plc, options, nullptr, detail::Folds::LeftAsTheyAre);
  take_refined(refined, options, stats, clock);
  if (refined.folds_left == 0) return std::nullopt;
  if (options.algorithm == Algorithm::CavitySweep) {
    if (std::optional<Triangulation<3>> tri = sweep_cavities(refined, options, stats, clock, nullptr)) return tri;
  } else {
    try {
      return triangulate(refined.plc, options, stats, clock);
    } catch (const NoCdtError&) {
      // the folds are needed
    }
  }
  ++stats.steiner_attempts;
  refined = {};
  refined = detail::refine(plc, options);
  take_refined(refined, options, stats, clock);
  return std::nullopt;
}

// The Delaunay tetrahedralization of plc's points that the importer's check computed meanwhile
// (kept_tetrahedralization.h), for the cavity sweep without refinement (refinement takes it itself):
// once, in `storage`, else null. Reports "Delaunay" progress while it waits for it.
const detail::DelaunayMesh* imported_tetrahedralization(const Plc<3>& plc, const Options& options, CdtStatistics& stats,
                                                        detail::DelaunayMesh& storage) {
  if (options.algorithm != Algorithm::CavitySweep) return nullptr;
  bool cancelled = false;
  const std::unique_ptr<detail::DelaunayEdges> kept = detail::take_kept_tetrahedralization(plc, [&](std::size_t inserted) {
    cancelled = options.progress && !options.progress({"Delaunay", inserted, plc.num_points()});
    return !cancelled;
  });
  if (cancelled) throw CancelledError();
  if (!kept) return nullptr;
  stats.tetrahedralization_recorded = true;
  storage = kept->mesh();
  return &storage;
}

// One run on a checked PLC, perturbed by vertex id: (Steiner points or coplanar facets,) the
// algorithm, neighbours, regions, validate(). `delaunay`: the Delaunay tetrahedralization of plc's
// points, when cdt() computed it beside the check.
template <int D>
Triangulation<D> run(const Plc<D>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock, Plc<D>* triangulated,
                     const detail::DelaunayMesh* delaunay = nullptr) {
  detail::DelaunayMesh imported;  // the importer's tetrahedralization, for the cavity sweep without refinement
  if constexpr (D == 3) {
    if (options.steiner == SteinerMode::Auto || options.facets == FacetMode::Coplanar) {
      detail::RefinedPlc refined;
      std::optional<Triangulation<3>> swept;  // found while refining
      if (options.steiner == SteinerMode::Auto) {
        if (options.algorithm == Algorithm::CavitySweep && all_float(plc.points)) swept = refine_lazily(plc, options, stats, clock, refined);
        if (!swept) swept = refine_every_segment(plc, options, stats, clock, refined);
      } else {
        ++stats.steiner_attempts;
        refined = detail::refine(plc, options);
        take_refined(refined, options, stats, clock);
        if (!delaunay) delaunay = imported_tetrahedralization(plc, options, stats, imported);  // after the facets' CDTs
      }
      if (!swept) {
        // Without Steiner points the refined PLC has the input's points, and their tetrahedralization.
        if (refined.delaunay) delaunay = &*refined.delaunay;
        else if (!refined.steiner_on.empty()) delaunay = nullptr;
      }
      Triangulation<3> tri = swept ? std::move(*swept) : triangulate(refined.plc, options, stats, clock, delaunay);
      refined.delaunay.reset();
      tri.num_input_points = refined.num_input_points;
      tri.steiner_on = std::move(refined.steiner_on);
      if (options.remove_steiner_points && !tri.steiner_on.empty()) {
        const detail::SteinerDeletions deletions = detail::remove_steiner_points(tri, refined.plc, refined.made_from, refined.off_input, options);
        stats.steiner_points_removed = deletions.removed;
        stats.steiner_deletions_tried = deletions.tried;
        stats.steiner_retries_skipped = deletions.skipped;
        stats.steiner_refused_early = deletions.refused_early;
        stats.steiner_points = tri.steiner_on.size();
        stats.seconds_finish += clock.lap();
      }
      if (!plc.tags.empty())
        for (auto& t : refined.plc.tags) t = plc.tags[t];
      if (triangulated) *triangulated = std::move(refined.plc);
      return tri;
    }
  }
  if constexpr (D == 3)
    if (!delaunay) delaunay = imported_tetrahedralization(plc, options, stats, imported);
  Triangulation<D> tri = triangulate(plc, options, stats, clock, delaunay);
  if (triangulated) *triangulated = plc;
  return tri;
}

// The same run perturbed in the order `rank` (paper §6): on the PLC with vertex v renamed rank[v]
// (relabel.h), its result renamed back.
template <int D>
Triangulation<D> run_in_order(const Plc<D>& plc, const std::vector<uint32_t>& rank, const Options& options, CdtStatistics& stats,
                              Stopwatch& clock, Plc<D>* triangulated) {
  Triangulation<D> tri = run(detail::relabeled(plc, rank), options, stats, clock, triangulated);
  detail::restore_ids(tri, triangulated, rank);
  tri.perturbation_rank = rank;
  return tri;
}

// Paper §6: "it is possible that such a triangulation does not exist, even if the unperturbed points
// have a CDT. The order in which the vertices are perturbed can determine whether or not a
// triangulation is discovered." When the PLC is triangulated as given and the run by vertex id finds
// no CDT, the next orders of perturbation_order.h are tried — but only while the failed runs met a
// cospherical tie (predicates/stats.h): a run that decided every sphere test without the
// perturbation decided nothing an order could change. At most kPerturbationOrders runs: each is a
// full run, and a PLC with ties but no CDT (a cospherical prism split Schönhardt's way, most real
// surfaces that need Steiner points) costs that many; 8 leaves room for the structured orders 0-5
// and two pseudo-random ones. The first run's error is reported, in the caller's ids.
template <int D>
Triangulation<D> run_with_retries(const Plc<D>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock,
                                  Plc<D>* triangulated, const detail::DelaunayMesh* delaunay) {
  const auto ties = [] { return predicates::perturbation_ties_on_this_thread(); };
  uint64_t ties_before = ties();
  std::optional<NoCdtError> first;
  stats.perturbation_orders = 1;
  try {
    return run(plc, options, stats, clock, triangulated, delaunay);
  } catch (const NoCdtError& e) {
    first = e;
  }
  const bool as_given = !(D == 3 && options.steiner == SteinerMode::Auto);  // Auto changes the PLC instead
  std::vector<std::vector<uint32_t>> tried{perturbation_rank(plc, 0)};
  for (int order = 1; as_given && order < kPerturbationOrders && ties() != ties_before; ++order) {
    std::vector<uint32_t> rank = perturbation_rank(plc, order);
    if (std::find(tried.begin(), tried.end(), rank) != tried.end()) continue;  // e.g. few points
    tried.push_back(rank);
    ++stats.perturbation_orders;
    Options in_order = options;
    if (options.progress)
      in_order.progress = [&](const Progress& p) {
        const std::string phase = std::string(p.phase) + " (perturbation order " + std::to_string(order) + ")";
        return options.progress({phase.c_str(), p.done, p.total});
      };
    ties_before = ties();
    try {
      Triangulation<D> tri = run_in_order(plc, rank, in_order, stats, clock, triangulated);
      stats.perturbation_order = static_cast<uint32_t>(order);
      return tri;
    } catch (const NoCdtError&) {
      // not under this order either: the next one, if this run met a tie
    }
  }
  if (stats.perturbation_orders == 1) throw *first;
  throw NoCdtError(std::string(first->what()) + " (and no CDT under any of the " + std::to_string(stats.perturbation_orders) +
                       " perturbation orders tried, paper §6)",
                   first->witness());
}

}  // namespace

template <int D>
Triangulation<D> cdt(const Plc<D>& plc, const Options& options, Plc<D>* triangulated) {
  CdtStatistics local;
  CdtStatistics& stats = options.statistics ? *options.statistics : local;
  stats = {};
  Stopwatch clock;
  stats.check_recorded = plc.checked && plc.checked->covers(plc);
  // The cavity sweep's Delaunay triangulation beside a full check, given a second thread (with
  // Steiner points, in 3D, refinement computes its own as it goes; other dimensions have none).
  const bool refines = D == 3 && options.steiner == SteinerMode::Auto;
  // An importer's tetrahedralization of the points (3D) serves refinement (run()) or, without it, the
  // cavity sweep; the other algorithms have no use for it: stopped.
  const bool sweeps_cavities = options.algorithm == Algorithm::CavitySweep && !refines;
  // Whatever run() did not claim of it stops with the call (refinement or the cavity sweep claims
  // it in the first run; the other algorithms not at all: stopped at once).
  struct DropUnclaimed {
    const Plc<D>& plc;
    ~DropUnclaimed() {
      if constexpr (D == 3) detail::drop_kept_tetrahedralization(plc);
    }
  } drop_unclaimed{plc};
  if constexpr (D == 3)
    if (!refines && !sweeps_cavities) detail::drop_kept_tetrahedralization(plc);
  // (A PLC whose record covers it needs no full check: run() takes the importer's, if any.)
  std::optional<detail::DelaunayInBackground<D>> delaunay;
  if (sweeps_cavities && !stats.check_recorded && detail::thread_count(options.threads) > 1) delaunay.emplace(plc.points);
  // The triangulation takes a thread of its own and the check the others: a check on every
  // thread competes with it for its core, and it is the longer of the two (1.3M triangles on 2
  // cores: a check on two threads took 2.1 s, then 1 s more of waiting; on one thread 2.4 s, then
  // about 0.5 s).
  check(plc, delaunay ? std::max(1u, detail::thread_count(options.threads) - 1) : options.threads);
  stats.seconds_check = clock.lap();
  const detail::DelaunayMesh* mesh = nullptr;
  if (delaunay) {
    bool cancelled = false;
    mesh = delaunay->get([&](std::size_t inserted) {
      cancelled = options.progress && !options.progress({"Delaunay", inserted, plc.num_points()});
      return !cancelled;
    });
    if (cancelled) throw CancelledError();
  }
  return run_with_retries(plc, options, stats, clock, triangulated, mesh);
}

template <int D>
Triangulation<D> cdt(const Plc<D>& plc, const Options& options) {
  return cdt(plc, options, static_cast<Plc<D>*>(nullptr));
}

template <int D>
Triangulation<D> star_cdt(const Plc<D>& polytope, const std::array<double, D>& centre, const Options& options) {
  CdtStatistics local;
  CdtStatistics& stats = options.statistics ? *options.statistics : local;
  stats = {};
  stats.perturbation_orders = 1;
  Stopwatch clock;
  check(polytope, options.threads);
  stats.seconds_check = clock.lap();
  return finish(detail::star_sweep_cdt<D>(polytope, centre, options, stats), polytope, options, stats, clock);
}

template Triangulation<2> star_cdt<2>(const Plc<2>&, const std::array<double, 2>&, const Options&);
template Triangulation<3> star_cdt<3>(const Plc<3>&, const std::array<double, 3>&, const Options&);
template Triangulation<4> star_cdt<4>(const Plc<4>&, const std::array<double, 4>&, const Options&);
template Triangulation<5> star_cdt<5>(const Plc<5>&, const std::array<double, 5>&, const Options&);
template Triangulation<2> cdt<2>(const Plc<2>&, const Options&);
template Triangulation<3> cdt<3>(const Plc<3>&, const Options&);
template Triangulation<4> cdt<4>(const Plc<4>&, const Options&);
template Triangulation<5> cdt<5>(const Plc<5>&, const Options&);
template Triangulation<2> cdt<2>(const Plc<2>&, const Options&, Plc<2>*);
template Triangulation<3> cdt<3>(const Plc<3>&, const Options&, Plc<3>*);
template Triangulation<4> cdt<4>(const Plc<4>&, const Options&, Plc<4>*);
template Triangulation<5> cdt<5>(const Plc<5>&, const Options&, Plc<5>*);

}  // namespace sweepcdt
