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
  bool bent = false;  // filled with sheets_without()'s `unbend`: its pieces not exactly coplanar, or v off its straight edge
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
// `unbend` (D = 3; EditableCdt::unbend_facets_at_steiner_points): same_facet names pieces of one
// input facet and v is a Steiner point, which rounding may have put a few ulps off its segment or
// its facet's plane. Then the pieces of one facet around v form one sheet even where they are not
// exactly coplanar, and a sheet on a segment is closed by the straight edge between v's two
// neighbours on it even when v is not exactly on that edge: the hole is filled as if v had never
// been made (its fill is a valid triangulation of the hole in projection; EditableCdt checks the
// cavity exactly, and refuses the deletion when the fill does not fit in it).
struct Unbend {
  uint32_t first_steiner;                          // ids from here on are Steiner points
  std::function<bool(uint32_t, uint32_t)> ridge;   // edge ab lies on pieces of two facets (looked up among a's constraints)
};
template <int D>
std::vector<Sheet<D>> sheets_without(uint32_t v, const std::vector<std::array<uint32_t, D>>& through_v,
                                     const std::function<const double*(uint32_t)>& point,
                                     const std::function<uint32_t(uint32_t)>& order,
                                     const std::function<bool(uint32_t, uint32_t)>& same_facet, const Unbend* unbend = nullptr,
                                     std::string* refusal = nullptr);

}  // namespace sweepcdt::detail
