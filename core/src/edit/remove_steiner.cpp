// Deleting Steiner points again (remove_steiner.h).
#include "remove_steiner.h"

#include <algorithm>
#include <deque>
#include <optional>

#include "../parallel.h"
#include "sweepcdt/editable_cdt.h"

namespace sweepcdt::detail {
namespace {

// 0..n-1 in bit-reversed order (0, n/2, n/4, 3n/4, ...): consecutive entries far apart.
std::vector<uint32_t> spread_order(uint32_t n) {
  int bits = 0;
  while ((uint64_t{1} << bits) < n) ++bits;
  std::vector<uint32_t> order;
  order.reserve(n);
  for (uint64_t i = 0; i < (uint64_t{1} << bits); ++i) {
    uint32_t reversed = 0;
    for (int b = 0; b < bits; ++b)
      if (i >> b & 1u) reversed |= 1u << (bits - 1 - b);
    if (reversed < n) order.push_back(reversed);
  }
  return order;
}

}  // namespace

SteinerDeletions remove_steiner_points(Triangulation<3>& tri, Plc<3>& plc, const std::vector<std::array<uint32_t, 2>>& made_from,
                               const std::vector<char>& off_input, const Options& options) {
  const uint32_t first = tri.num_input_points, end = static_cast<uint32_t>(tri.num_points());
  // The input facets (tags) whose points all lie exactly in their planes: most, on float surfaces.
  std::vector<char> flat_by_tag(plc.tags.empty() ? 0 : *std::max_element(plc.tags.begin(), plc.tags.end()) + std::size_t{1}, 1);
  for (std::size_t c = 0; c < plc.tags.size(); ++c)
    if (c >= off_input.size() || off_input[c]) flat_by_tag[plc.tags[c]] = 0;
  EditableCdt<3> mesh(std::move(plc), std::move(tri));
  mesh.unbend_facets_at_steiner_points(kLargestBentStar);  // plc's tags name input facets (cdt.cpp)
  mesh.know_flat_facets(std::move(flat_by_tag));  // their orientation tests: 4% of perforated_tube_std's pass
  // A point rounded off its segment (double coordinates) whose merged segment is blocked by its
  // star's vertices is refused without its star CDT, which nearly always refuses it too: a wrong
  // guess keeps one point more, the CDT is still checked (EditableCdt::guess_blocked_refusals).
  mesh.guess_blocked_refusals(true);
  // A point whose deletion would fill its cavity with more than three times its star's tetrahedra
  // stays: on thin walls such deletions took perforated_tube_std from 222875 tetrahedra (refinement's
  // 82306 points) to 513781 (55809 points), against 227397 now (56652 points; tetgen -pQ: 136830 with
  // 45192), 0.86x the time (EditableCdt::limit_growth).
  mesh.limit_growth(kGrowthFactor);
  // Per Steiner point: how many points made from it are still there; it is tried only at 0.
  std::vector<uint32_t> children(end - first, 0);
  for (const auto& pair : made_from)
    for (uint32_t parent : pair)
      if (parent >= first) ++children[parent - first];
  // A work list: a point that stays is tried again only when a neighbour goes (only then can the
  // answer change: the rest of the CDT and of the PLC is the same), or when its last child goes.
  std::deque<uint32_t> work;
  std::vector<char> queued(end - first, 0);
  const auto enqueue = [&](uint32_t w) {
    if (w >= first && !queued[w - first] && children[w - first] == 0) queued[w - first] = 1, work.push_back(w);
  };
  // A point tried again because a neighbour went is skipped unless that neighbour, or another that
  // went since, bears on its refusal: a vertex of the refusal's witness (mostly the simplex the star
  // sweep found in front of a face built after it) or of a constraint through the point (its
  // facets' pieces change when it goes). While none of those go, the refusal stays, nearly always:
  // on 164 CAD parts, prints and scans (session 23) 160 meshes are byte-identical to trying every
  // such point again, three with double coordinates keep 1, 2 and 9 points more, one as many in
  // other places; 5.9% of the attempts are skipped (up to 23%), all of them refusals. Skipped where
  // it would have been tried, the list runs as before; only which points are tried is a heuristic.
  // A refusal found before the star CDT (EditableCdt's early refusal: the piece left would not be
  // Delaunay; most refusals on float surfaces) has a witness that proves it: while the merged
  // segment's ends and the three vertices that block it stay, it stands, so skipping those retries
  // changes nothing (perforated_tube_std: 13882 of 104314 early refusals skipped, the same mesh).
  std::vector<std::vector<uint32_t>> refused_by(end - first);  // sorted; empty: try it
  const auto unsettle = [&](uint32_t w, uint32_t gone) {
    if (w < first) return;
    auto& why = refused_by[w - first];
    if (std::binary_search(why.begin(), why.end(), gone)) why.clear();
  };
  // First every point, spread out: refinement makes them one after another along each segment, and
  // deleting neighbours one after another grows each next cavity by the last one's (a segment's
  // pieces merge into ever longer ones: stars of 60 tetrahedra and more on the pipe tees). In
  // bit-reversed order of their creation (the last made first) each attempt is mostly a point's
  // own star, and the plans of several threads rarely overlap (pipe_tee_fine, one thread: 106725
  // attempts in 12.8 s before, 108439 in 9.4 s; 27074 points kept before, 27408 now).
  for (const uint32_t k : spread_order(end - first)) enqueue(end - 1 - k);
  // With several threads the deletions of the next points on the list are worked out at once
  // (EditableCdt::plan_removal) and applied in list order, as long as the next plan is current; a
  // plan that an earlier deletion made stale (it changed the plan's star) is worked out again with
  // the next ones. So the result is one thread's, deletion by deletion. Most plans stay current:
  // most attempts are refused, and refusals change nothing.
  const unsigned threads = end - first < kPointsForThreads ? 1 : thread_count(options.threads);
  std::optional<WorkerPool> pool;
  if (threads > 1) pool.emplace(threads - 1);
  // Enough plans to keep the threads busy, few enough that few go stale; one thread plans one.
  const std::size_t batch = threads > 1 ? 4 * std::size_t{threads} : 1;
  // While the helpers finish the batch's last plans, this thread plans the next ones on the list
  // (reading the mesh, as they do); those still current when their turn comes are not made again.
  const std::size_t lookahead = threads > 1 ? batch : 0;
  std::deque<EditableCdt<3>::Removal> plans;  // plans[i] for work[i]
  std::vector<std::size_t> to_plan;
  std::vector<uint32_t> neighbours, witness;
  const std::function<void(std::size_t)> plan = [&](std::size_t k) { plans[to_plan[k]] = mesh.plan_removal(work[to_plan[k]]); };
  SteinerDeletions count;
  while (!work.empty()) {
    const std::size_t n = std::min(batch, work.size());
    // Sized before the threads start: a plan is written in place, and the deque does not grow meanwhile.
    while (plans.size() < std::min(n + lookahead, work.size())) plans.emplace_back();
    to_plan.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (refused_by[work[i] - first].empty() && !mesh.plan_is_current(plans[i])) to_plan.push_back(i);
    if (pool && to_plan.size() > 1) {
      std::size_t next = n;
      const std::function<bool()> plan_ahead = [&] {
        while (next < plans.size() && (!refused_by[work[next] - first].empty() || mesh.plan_is_current(plans[next]))) ++next;
        if (next == plans.size()) return false;
        plans[next] = mesh.plan_removal(work[next]);
        ++next;
        return true;
      };
      pool->run(to_plan.size(), plan, {}, plan_ahead);
    } else {
      for (std::size_t k = 0; k < to_plan.size(); ++k) plan(k);
    }
    do {
      const uint32_t v = work.front();  // new entries go to the back: the planned ones stay in front
      work.pop_front();
      queued[v - first] = 0;
      EditableCdt<3>::Removal removal = std::move(plans.front());
      plans.pop_front();
      if (!refused_by[v - first].empty()) {
        ++count.skipped;
        continue;
      }
      // Refused when the PLC without v has no CDT (v is needed), or v is a junction of several
      // facets (pieces of one input facet around it are one sheet, bent by rounding or not), or v
      // lies off its segment and the segment it would leave is blocked (the guess above).
      if (mesh.try_commit_removal(std::move(removal), neighbours, &witness)) {
        ++count.removed;
        for (uint32_t parent : made_from[v - first])
          if (parent >= first) --children[parent - first];
        for (uint32_t w : neighbours) unsettle(w, v), enqueue(w);
        for (uint32_t parent : made_from[v - first]) enqueue(parent);
      } else if (!witness.empty()) {  // a NoCdtError (a VertexRemovalError is tried again whoever goes)
        std::vector<uint32_t>& why = refused_by[v - first];
        why = mesh.constraint_neighbours(v);
        why.insert(why.end(), witness.begin(), witness.end());
        std::sort(why.begin(), why.end());
      }
      ++count.tried;
      if (options.progress && (count.tried & 255) == 0 && !options.progress({"removing Steiner points", count.tried, end - first}))
        throw CancelledError();
    } while (!plans.empty() && mesh.plan_is_current(plans.front()));
  }
  count.refused_early = mesh.refused_early();
  EditableCdt<3>::Snapshot result = std::move(mesh).release();
  tri = std::move(result.triangulation);
  plc = std::move(result.plc);
  return count;
}

}  // namespace sweepcdt::detail
