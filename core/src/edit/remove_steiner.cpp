// Deleting Steiner points again (remove_steiner.h).
#include "remove_steiner.h"

#include <deque>

#include "sweepcdt/editable_cdt.h"

namespace sweepcdt::detail {

uint64_t remove_steiner_points(Triangulation<3>& tri, Plc<3>& plc, const std::vector<std::array<uint32_t, 2>>& made_from,
                               const Options& options) {
  const uint32_t first = tri.num_input_points, end = static_cast<uint32_t>(tri.num_points());
  EditableCdt<3> mesh(std::move(plc), std::move(tri));
  // Per Steiner point: how many points made from it are still there; it is tried only at 0.
  std::vector<uint32_t> children(end - first, 0);
  for (const auto& pair : made_from)
    for (uint32_t parent : pair)
      if (parent >= first) ++children[parent - first];
  // A work list, last added first (children before their parents): a point that stays is tried
  // again only when a neighbour goes (only then can the answer change: the rest of the CDT and of
  // the PLC is the same), or when its last child goes.
  std::deque<uint32_t> work;
  std::vector<char> queued(end - first, 0);
  const auto enqueue = [&](uint32_t w) {
    if (w >= first && !queued[w - first] && children[w - first] == 0) queued[w - first] = 1, work.push_back(w);
  };
  for (uint32_t v = end; v-- > first;) enqueue(v);
  uint64_t removed = 0, tried = 0;
  while (!work.empty()) {
    const uint32_t v = work.front();
    work.pop_front();
    queued[v - first] = 0;
    try {
      const std::vector<uint32_t> neighbours = mesh.remove_vertex(v);
      ++removed;
      for (uint32_t parent : made_from[v - first])
        if (parent >= first) --children[parent - first];
      for (uint32_t w : neighbours) enqueue(w);
      for (uint32_t parent : made_from[v - first]) enqueue(parent);
    } catch (const NoCdtError&) {
      // needed: the PLC without it has no CDT
    } catch (const VertexRemovalError&) {
      // a corner of a facet (a rounded point off its segment), or a junction of several facets
    }
    if (options.progress && (++tried & 255) == 0 && !options.progress({"removing Steiner points", tried, end - first}))
      throw CancelledError();
  }
  EditableCdt<3>::Snapshot result = mesh.snapshot();
  tri = std::move(result.triangulation);
  plc = std::move(result.plc);
  return removed;
}

}  // namespace sweepcdt::detail
