#include "sweepcdt/triangulation.h"

#include "facets.h"

namespace sweepcdt {

template <int D>
void compute_neighbors(Triangulation<D>& tri) {
  tri.neighbors.assign(tri.simplices.size(), kNone);
  const auto facets = detail::sorted_facets(tri);
  detail::for_each_facet_group<D>(facets, [&](std::size_t begin, std::size_t end) {
    if (end - begin != 2) return;
    const auto& a = facets[begin];
    const auto& b = facets[begin + 1];
    tri.neighbors[(D + 1) * a.simplex + a.local] = (D + 1) * b.simplex + b.local;
    tri.neighbors[(D + 1) * b.simplex + b.local] = (D + 1) * a.simplex + a.local;
  });
}

template void compute_neighbors<2>(Triangulation<2>&);
template void compute_neighbors<3>(Triangulation<3>&);
template void compute_neighbors<4>(Triangulation<4>&);
template void compute_neighbors<5>(Triangulation<5>&);

}  // namespace sweepcdt
