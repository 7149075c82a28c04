#include "relabel.h"

#include <algorithm>

namespace sweepcdt::detail {
namespace {

// ids[k] -> map[ids[k]] for ids below map.size().
void rename(std::vector<uint32_t>& ids, const std::vector<uint32_t>& map) {
  for (uint32_t& id : ids)
    if (id < map.size()) id = map[id];
}

// Point v of `points` moves to index map[v] (v < map.size()); the others stay.
template <int D>
void move_points(std::vector<double>& points, const std::vector<uint32_t>& map) {
  std::vector<double> moved = points;
  for (std::size_t v = 0; v < map.size(); ++v)
    std::copy_n(points.begin() + v * D, D, moved.begin() + std::size_t{map[v]} * D);
  points = std::move(moved);
}

// Renames `points` (n x D) and `simplices` by `map`: point v moves to map[v], ids follow.
template <int D>
void apply(std::vector<double>& points, std::vector<uint32_t>& simplices, const std::vector<uint32_t>& map) {
  move_points<D>(points, map);
  rename(simplices, map);
}

std::vector<uint32_t> inverse(const std::vector<uint32_t>& rank) {
  std::vector<uint32_t> inv(rank.size());
  for (uint32_t v = 0; v < rank.size(); ++v) inv[rank[v]] = v;
  return inv;
}

}  // namespace

template <int D>
Plc<D> relabeled(const Plc<D>& plc, const std::vector<uint32_t>& rank) {
  Plc<D> out = plc;
  apply<D>(out.points, out.simplices, rank);
  return out;
}

template <int D>
void restore_ids(Triangulation<D>& tri, Plc<D>* triangulated, const std::vector<uint32_t>& rank) {
  const std::vector<uint32_t> back = inverse(rank);
  apply<D>(tri.points, tri.simplices, back);
  if (triangulated) apply<D>(triangulated->points, triangulated->simplices, back);
}

#define SWEEPCDT_INSTANTIATE(D)                                                      \
  template Plc<D> relabeled<D>(const Plc<D>&, const std::vector<uint32_t>&);         \
  template void restore_ids<D>(Triangulation<D>&, Plc<D>*, const std::vector<uint32_t>&);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::detail
