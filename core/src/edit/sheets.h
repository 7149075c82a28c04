// The facets through a vertex being deleted (paper §5, "the (d-1)-dimensional CDT of the facet's
// polygon without v"): the constraining simplices through v fall into sheets — exactly coplanar
// neighbours across manifold ridges through v — and each sheet without v is triangulated anew.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace sweepcdt::detail {

template <int D>
struct Sheet {
  std::vector<uint32_t> constraints;          // indices into the `through_v` argument below
  std::vector<std::array<uint32_t, D>> fill;  // the sheet without v: new constraining simplices, each
                                              // oriented like through_v[constraints[0]] in its hyperplane
};

// `through_v`: the constraining simplices holding v; `point(id)` its coordinates; `order(id)` the
// perturbation order of the points (§6), which the fill's CDT keeps; `same_facet(i, j)` whether
// through_v[i] and through_v[j] may be one facet (a sheet never joins two that may not). When v is a
// corner of a sheet (or on a sheet boundary this code does not handle: D = 2 or D >= 4), or a sheet
// has no CDT without it: throws VertexRemovalError, or, given `refusal`, stores the same message there
// and returns no sheet (a deletion pass meets this in most attempts it refuses).
template <int D>
std::vector<Sheet<D>> sheets_without(uint32_t v, const std::vector<std::array<uint32_t, D>>& through_v,
                                     const std::function<const double*(uint32_t)>& point,
                                     const std::function<uint32_t(uint32_t)>& order,
                                     const std::function<bool(uint32_t, uint32_t)>& same_facet, std::string* refusal = nullptr);

}  // namespace sweepcdt::detail
