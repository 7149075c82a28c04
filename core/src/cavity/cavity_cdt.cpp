#include "cavity_cdt.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <limits>
#include <thread>

#include "sweepcdt/predicates/perturbation.h"
#include "sweepcdt/validate.h"

#include "../facets.h"
#include "../gift_wrap.h"
#include "../parallel.h"
#include "../sweep/sweep_cdt.h"
#include "../tuple_map.h"
#include "cavity_plc.h"
#include "disturbed.h"
#include "domain_sides.h"

namespace sweepcdt::detail {
namespace {

// Step 5: the kept simplices, with their adjacency from the Delaunay mesh, and the cavities'
// simplices (in the PLC's ids), paired by their facets with each other and with the kept facets that
// face a cavity. Facets on the domain's boundary keep kNone. `not_delaunay`, when given, gets the
// index (among the cavity simplices) of each cavity simplex whose circumsphere holds the apex of a
// kept simplex across a facet (perturbed, as validate() tests it): when the PLC has no CDT, each
// cavity can still have one, and this is where they do not fit together.
template <int D>
Triangulation<D> assemble(const Plc<D>& plc, const DelaunayMesh& dt, const std::vector<Place>& place,
                          const std::vector<uint32_t>& cavity_simplices, std::vector<uint32_t>* not_delaunay = nullptr) {
  constexpr uint32_t kVertices = D + 1;
  std::vector<uint32_t> renumbered(place.size(), kNone);
  uint32_t kept = 0;
  for (std::size_t t = 0; t < place.size(); ++t)
    if (place[t] == Place::Inside) renumbered[t] = kept++;
  Triangulation<D> tri = triangulation_of<D>(plc, {});
  tri.simplices.reserve(kVertices * std::size_t{kept} + cavity_simplices.size());
  tri.neighbors.reserve(tri.simplices.capacity());
  TupleMap<D> open(cavity_simplices.size());  // facet -> (D+1) simplex + local index, its first side seen
  const auto pair = [&](const uint32_t* simplex, uint32_t s, uint32_t i) {
    const auto [other, first] = open.emplace(facet_key<D>(simplex, i), kVertices * s + i);
    if (first) return;
    tri.neighbors[kVertices * s + i] = other;
    tri.neighbors[other] = kVertices * s + i;
    if (not_delaunay && s >= kept && other / kVertices < kept) {
      predicates::Vertices<D + 1> cell;
      for (uint32_t k = 0; k < kVertices; ++k) cell[k] = {plc.point(simplex[k]), simplex[k]};
      const uint32_t apex = tri.simplices[other];  // facet `other % kVertices` is opposite that vertex
      if (predicates::inside_circumsphere<D>(cell, {plc.point(apex), apex})) not_delaunay->push_back(s - kept);
    }
  };
  for (std::size_t t = 0; t < place.size(); ++t) {
    if (place[t] != Place::Inside) continue;
    const uint32_t s = renumbered[t];
    for (uint32_t i = 0; i < kVertices; ++i) {
      tri.simplices.push_back(dt.tets[kVertices * t + i]);
      const uint32_t nb = dt.neighbors[kVertices * t + i];
      const bool inside = nb != kNone && renumbered[nb / kVertices] != kNone;
      tri.neighbors.push_back(inside ? kVertices * renumbered[nb / kVertices] + nb % kVertices : kNone);
    }
    for (uint32_t i = 0; i < kVertices; ++i) {
      const uint32_t nb = dt.neighbors[kVertices * t + i];
      if (nb != kNone && place[nb / kVertices] == Place::Cavity) pair(&dt.tets[kVertices * t], s, i);
    }
  }
  for (std::size_t k = 0; k < cavity_simplices.size() / kVertices; ++k) {
    const uint32_t s = kept + static_cast<uint32_t>(k);
    tri.simplices.insert(tri.simplices.end(), &cavity_simplices[kVertices * k], &cavity_simplices[kVertices * k] + kVertices);
    tri.neighbors.insert(tri.neighbors.end(), kVertices, kNone);
    for (uint32_t i = 0; i < kVertices; ++i) pair(&cavity_simplices[kVertices * k], s, i);
  }
  return tri;
}

// One cavity swept (step 4): its CDT's simplices, in the PLC's ids (the rest of its triangulation
// is dropped in the job), or failed.
struct Swept {
  std::vector<uint32_t> simplices;
  bool failed = false;
  CdtStatistics stats;  // the sweep's counters
};

// Every cavity swept, on options.threads threads: the cavities are independent (the domain split by
// the kept Delaunay simplices), so each is one job, the largest first; the results do not depend on
// the threads. Without `validate_each` the sweeps stop at the first failure (the caller gives up
// then). Progress is reported from the calling thread only (a callback need not be thread-safe):
// from its sweeps, after each cavity it sweeps and once at the end ("cavities": swept of all);
// when it cancels, every sweep stops and CancelledError is thrown.
template <int D>
std::vector<Swept> sweep_each(const Cavities<D>& cavities, const Options& options, bool validate_each) {
  const std::size_t n = cavities.parts.size();
  std::vector<Swept> swept(n);
  std::vector<std::size_t> order(n);
  for (std::size_t c = 0; c < n; ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cavities.parts[a].plc.num_points() > cavities.parts[b].plc.num_points(); });
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> stop{false}, cancelled{false};
  Options each = options;
  each.threads = 1;
  if (options.progress)
    each.progress = [&](const Progress& p) {
      if (cancelled.load(std::memory_order_relaxed)) return false;
      if (std::this_thread::get_id() != caller || options.progress(p)) return true;
      cancelled = true;
      return false;
    };
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> done{0};
  const auto report = [&](std::size_t swept_now) {
    if (options.progress && !cancelled && !options.progress({"cavities", swept_now, n})) cancelled = true;
  };
  const std::function<void(std::size_t)> sweep = [&](std::size_t k) {
    const std::size_t c = order[k];
    if (stop.load(std::memory_order_relaxed)) return;
    const Plc<D>& plc = cavities.parts[c].plc;
    Swept& part = swept[c];
    try {
      Triangulation<D> tri = sweep_cavity<D>(plc, each, part.stats);
      // Without a CDT the sweep can also end with a triangulation that is none (a triangular
      // bipyramid whose two constraints meet at an edge that is not Delaunay: two tetrahedra, not
      // locally Delaunay between them); validate() finds that later, for the whole. Lazy refinement
      // needs the cavity, so it validates each.
      if (validate_each) {
        compute_neighbors(tri);
        part.failed = !validate<D>(tri, plc, ValidationLevel::Full, 1).ok();
      }
      part.simplices = std::move(tri.simplices);
      for (uint32_t& v : part.simplices) v = cavities.parts[c].global[v];
    } catch (const NoCdtError&) {
      part.failed = true;
      if (!validate_each) stop = true;
    } catch (...) {
      errors[c] = std::current_exception();
      stop = true;
    }
    const std::size_t swept_now = ++done;
    if (std::this_thread::get_id() == caller) report(swept_now);
  };
  const unsigned threads = n > 1 ? std::min<unsigned>(thread_count(options.threads), static_cast<unsigned>(n)) : 1;
  if (threads > 1) {
    WorkerPool(threads - 1).run(n, sweep, [&] { report(done.load()); });  // cancellable while a helper sweeps
  } else {
    for (std::size_t k = 0; k < n; ++k) sweep(k);
  }
  for (const std::exception_ptr& e : errors)
    if (e && !cancelled) std::rethrow_exception(e);
  if (n > 0) report(n);
  if (cancelled) throw CancelledError();
  return swept;
}

}  // namespace

template <int D>
Triangulation<D> sweep_cavity(const Plc<D>& plc, const Options& options, CdtStatistics& stats, int* along) {
  if constexpr (D == 3) {
    std::array<double, D> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t x = 0; x < plc.num_points(); ++x)
      for (int k = 0; k < D; ++k) lo[k] = std::min(lo[k], plc.point(x)[k]), hi[k] = std::max(hi[k], plc.point(x)[k]);
    int axis = 0;
    for (int k = 1; k < D; ++k)
      if (hi[k] - lo[k] < hi[axis] - lo[axis]) axis = k;
    if (along) *along = axis;
    if (axis == 0) return sweep_cdt<D>(plc, std::nullopt, options, stats);
    // (x, y, z) -> (y, z, x) or (z, x, y): a cyclic permutation of three axes is even.
    Plc<D> turned = plc;
    for (std::size_t x = 0; x < plc.num_points(); ++x)
      for (int k = 0; k < D; ++k) turned.points[x * D + k] = plc.points[x * D + (k + axis) % D];
    Triangulation<D> tri = sweep_cdt<D>(turned, std::nullopt, options, stats);
    tri.points = plc.points;
    return tri;
  } else {
    if (along) *along = -1;
    return sweep_cdt<D>(plc, seed_simplex(plc), options, stats);
  }
}

template <int D>
std::optional<Triangulation<D>> cavity_cdt(const Plc<D>& plc, const Options& options, CdtStatistics& stats,
                                           const DelaunayMesh* delaunay, std::vector<std::array<uint32_t, 2>>* failed_edges,
                                           const std::function<void()>& all_swept) {
  const std::size_t n = plc.num_points();
  DelaunayMesh computed;
  if (!delaunay) {
    try {
      computed = delaunay_mesh<D>(plc.points, [&](std::size_t inserted) {
        if (options.progress && !options.progress({"Delaunay", inserted, n})) throw CancelledError();
      });
    } catch (const CancelledError&) {
      throw;
    } catch (const Error&) {
      return std::nullopt;  // e.g. all points in one hyperplane
    }
    delaunay = &computed;
  }
  const DelaunayMesh& dt = *delaunay;
  const ConstraintFaces constraints = constraint_faces<D>(plc, dt, options.threads);
  stats.missing_constraints = constraints.missing.size();
  const Disturbed disturbed = disturbed_simplices<D>(plc, dt, constraints.missing, options.threads);
  if (disturbed.tets.size() != dt.tets.size() / (D + 1)) return std::nullopt;
  const std::vector<Place> place = domain_sides<D>(plc, dt, constraints.of_facet, disturbed.tets, options.threads);
  if (place.empty()) return std::nullopt;
  for (const Place p : place) stats.cavity_tetrahedra += p == Place::Cavity;
  const Cavities<D> cavities = cavity_plcs<D>(plc, dt, constraints.of_facet, constraints.missing, disturbed.first, place);
  if (cavities.reaches_hull) return std::nullopt;

  // With failed_edges, every cavity is swept, and the facets' edges of each that finds no CDT, or
  // whose CDT does not fit its kept neighbours, are reported.
  const auto report = [&](const CavityPlc<D>& cavity) {
    const std::vector<uint32_t>& s = cavity.plc.simplices;
    for (std::size_t f = 0; f < s.size(); f += D)
      for (int i = 0; i < D; ++i)
        for (int j = i + 1; j < D; ++j) failed_edges->push_back({cavity.global[s[f + i]], cavity.global[s[f + j]]});
  };
  std::vector<Swept> swept = sweep_each(cavities, options, failed_edges != nullptr);
  std::vector<uint32_t> cavity_simplices;
  std::vector<uint32_t> cavity_of;  // per cavity simplex, with failed_edges: its cavity
  bool failed = false;
  // The sweeps' counters are counted only when every cavity was swept: after a failure, which of the
  // others the threads swept before they stopped depends on the timing.
  if (failed_edges || std::none_of(swept.begin(), swept.end(), [](const Swept& part) { return part.failed; }))
    for (const Swept& part : swept) {
      stats.queue_pushes += part.stats.queue_pushes, stats.queue_pops += part.stats.queue_pops;
      stats.stale_pops += part.stats.stale_pops, stats.drop_moves += part.stats.drop_moves;
    }
  for (std::size_t c = 0; c < cavities.parts.size(); ++c) {
    Swept& part = swept[c];
    if (part.failed) {
      // The PLC has no CDT: the whole sweep finds out again and names a witness.
      if (!failed_edges) return std::nullopt;
      failed = true;
      report(cavities.parts[c]);
      continue;
    }
    cavity_simplices.insert(cavity_simplices.end(), part.simplices.begin(), part.simplices.end());
    if (failed_edges) cavity_of.insert(cavity_of.end(), part.simplices.size() / (D + 1), static_cast<uint32_t>(c));
    part.simplices = {};
  }
  if (failed) return std::nullopt;
  if (all_swept) all_swept();
  if (!failed_edges) return assemble<D>(plc, dt, place, cavity_simplices);
  std::vector<uint32_t> not_delaunay;
  Triangulation<D> tri = assemble<D>(plc, dt, place, cavity_simplices, &not_delaunay);
  if (not_delaunay.empty()) return tri;
  std::vector<char> reported(cavities.parts.size(), 0);
  for (const uint32_t k : not_delaunay)
    if (!reported[cavity_of[k]]) reported[cavity_of[k]] = 1, report(cavities.parts[cavity_of[k]]);
  return std::nullopt;
}

template Triangulation<2> sweep_cavity<2>(const Plc<2>&, const Options&, CdtStatistics&, int*);
template Triangulation<3> sweep_cavity<3>(const Plc<3>&, const Options&, CdtStatistics&, int*);
template Triangulation<4> sweep_cavity<4>(const Plc<4>&, const Options&, CdtStatistics&, int*);
template Triangulation<5> sweep_cavity<5>(const Plc<5>&, const Options&, CdtStatistics&, int*);
template std::optional<Triangulation<2>> cavity_cdt<2>(const Plc<2>&, const Options&, CdtStatistics&, const DelaunayMesh*,
                                                          std::vector<std::array<uint32_t, 2>>*, const std::function<void()>&);
template std::optional<Triangulation<3>> cavity_cdt<3>(const Plc<3>&, const Options&, CdtStatistics&, const DelaunayMesh*,
                                                          std::vector<std::array<uint32_t, 2>>*, const std::function<void()>&);
template std::optional<Triangulation<4>> cavity_cdt<4>(const Plc<4>&, const Options&, CdtStatistics&, const DelaunayMesh*,
                                                          std::vector<std::array<uint32_t, 2>>*, const std::function<void()>&);
template std::optional<Triangulation<5>> cavity_cdt<5>(const Plc<5>&, const Options&, CdtStatistics&, const DelaunayMesh*,
                                                          std::vector<std::array<uint32_t, 2>>*, const std::function<void()>&);

}  // namespace sweepcdt::detail
