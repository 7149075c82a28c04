// cdt(): check the PLC, run the chosen algorithm, pair neighbours, assign regions — and verify the
// result before returning it: a PLC without a CDT must fail with NoCdtError, never return a wrong
// triangulation.
#include "sweepcdt/cdt.h"

#include <chrono>

#include "gift_wrap.h"
#include "regions.h"
#include "steiner/refine.h"
#include "sweep/sweep_cdt.h"
#include "sweepcdt/validate.h"

namespace sweepcdt {

const char* to_string(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::SweepSphere: return "sweep-sphere";
    case Algorithm::SweepPlane: return "sweep-plane";
    case Algorithm::GiftWrap: return "giftwrap";
  }
  return "unknown";
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

template <int D>
Triangulation<D> build(const Plc<D>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock) {
  // The sweep plane needs the domain's left boundary: it has it for facet-bounded domains only.
  stats.algorithm = options.algorithm == Algorithm::SweepPlane && !plc.facet_bounded() ? Algorithm::SweepSphere : options.algorithm;
  switch (stats.algorithm) {
    case Algorithm::GiftWrap:
      return detail::gift_wrap(plc, options);
    case Algorithm::SweepPlane:
      return detail::sweep_cdt<D>(plc, std::nullopt, options, stats);
    case Algorithm::SweepSphere: {
      const auto delta = detail::seed_simplex(plc);
      stats.seconds_setup += clock.lap();
      return detail::sweep_cdt<D>(plc, delta, options, stats);
    }
  }
  return {};
}


// Triangulates `plc` (already checked) and verifies the result.
template <int D>
Triangulation<D> triangulate(const Plc<D>& plc, const Options& options, CdtStatistics& stats, Stopwatch& clock) {
  Triangulation<D> tri = build(plc, options, stats, clock);
  stats.seconds_build += clock.lap();
  stats.simplices = tri.num_simplices();
  compute_neighbors(tri);
  detail::assign_regions(tri, plc);
  const ValidationReport report = validate(tri, plc);
  stats.seconds_finish += clock.lap();
  if (!report.ok())
    throw NoCdtError("no CDT: the constructed triangulation fails validation (" + report.failures.front().check + ": " +
                         report.failures.front().detail + ")",
                     {});
  return tri;
}

}  // namespace

template <int D>
Triangulation<D> cdt(const Plc<D>& plc, const Options& options, Plc<D>* triangulated) {
  CdtStatistics local;
  CdtStatistics& stats = options.statistics ? *options.statistics : local;
  stats = {};
  Stopwatch clock;
  check(plc);
  stats.seconds_check = clock.lap();
  if constexpr (D == 3) {
    if (options.steiner == SteinerMode::Auto || options.facets == FacetMode::Coplanar) {
      detail::RefinedPlc refined = detail::refine(plc, options);
      stats.steiner_points = refined.steiner_on.size();
      stats.steiner_rounds = refined.rounds;
      stats.facets = refined.facets;
      stats.facet_flips = refined.flips;
      if (!plc.tags.empty())
        for (auto& t : refined.original) t = plc.tags[t];
      refined.plc.tags = refined.original;
      check(refined.plc);  // rounding of the split points must not have broken the PLC
      stats.seconds_setup += clock.lap();
      Triangulation<3> tri = triangulate(refined.plc, options, stats, clock);
      tri.num_input_points = refined.num_input_points;
      tri.steiner_on = std::move(refined.steiner_on);
      if (triangulated) *triangulated = std::move(refined.plc);
      return tri;
    }
  }
  Triangulation<D> tri = triangulate(plc, options, stats, clock);
  if (triangulated) *triangulated = plc;
  return tri;
}

template <int D>
Triangulation<D> cdt(const Plc<D>& plc, const Options& options) {
  return cdt(plc, options, static_cast<Plc<D>*>(nullptr));
}

template Triangulation<2> cdt<2>(const Plc<2>&, const Options&);
template Triangulation<3> cdt<3>(const Plc<3>&, const Options&);
template Triangulation<4> cdt<4>(const Plc<4>&, const Options&);
template Triangulation<5> cdt<5>(const Plc<5>&, const Options&);
template Triangulation<2> cdt<2>(const Plc<2>&, const Options&, Plc<2>*);
template Triangulation<3> cdt<3>(const Plc<3>&, const Options&, Plc<3>*);
template Triangulation<4> cdt<4>(const Plc<4>&, const Options&, Plc<4>*);
template Triangulation<5> cdt<5>(const Plc<5>&, const Options&, Plc<5>*);

}  // namespace sweepcdt
