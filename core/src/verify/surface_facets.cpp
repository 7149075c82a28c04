#include "surface_facets.h"

#include <algorithm>
#include <numeric>
#include <tuple>

#include "../ids_text.h"
#include "sweepcdt/predicates.h"

namespace sweepcdt::detail {
namespace {

struct EdgeUse {
  uint32_t a, b;      // sorted vertex ids
  uint32_t triangle;
  int k;              // the triangle's edge k: (v_k, v_{k+1})
};

uint32_t root(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// The Coplanar rule for an edge with exactly the triangles of uses s and t: exactly coplanar. The
// rule also asks for the material on the same side, which holds for every such edge of a surface
// from io::import_plc: both triangles bound one shell, and the exterior notations carry any
// triangle the importer found reversed.
bool same_facet(const Plc<3>& input, const EdgeUse& s, const EdgeUse& t) {
  const uint32_t* a = input.simplex(s.triangle);
  const uint32_t d = input.simplex(t.triangle)[(t.k + 2) % 3];
  return predicates::orient<3>({input.point(a[0]), input.point(a[1]), input.point(a[2]), input.point(d)}) == predicates::Sign::Zero;
}

}  // namespace

std::string SurfaceFacets::name(uint32_t facet, const Plc<3>& input) const {
  const auto& t = triangles[facet];
  if (t.size() == 1) return "input triangle " + std::to_string(t[0]) + " " + ids_text(input.simplex(t[0]), 3);
  std::string s = "the coplanar facet of input triangles ";
  for (std::size_t k = 0; k < t.size() && k < 3; ++k) s += (k ? ", " : "") + std::to_string(t[k]);
  return s + (t.size() > 3 ? ", ..." : "") + " (" + std::to_string(t.size()) + " triangles)";
}

std::array<uint32_t, 3> material_positive(const Plc<3>& input, uint32_t j) {
  const uint32_t* t = input.simplex(j);
  if (input.exterior_of(j) == ExteriorSide::Negative) return {t[0], t[1], t[2]};
  return {t[0], t[2], t[1]};
}

SurfaceFacets group_surface_facets(const Plc<3>& input, FacetMode mode) {
  SurfaceFacets g;
  g.mode = mode;
  const uint32_t m = static_cast<uint32_t>(input.num_simplices());
  std::vector<EdgeUse> uses;
  uses.reserve(3 * std::size_t{m});
  for (uint32_t j = 0; j < m; ++j)
    for (int k = 0; k < 3; ++k) {
      const uint32_t p = input.simplex(j)[k], q = input.simplex(j)[(k + 1) % 3];
      uses.push_back({std::min(p, q), std::max(p, q), j, k});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.a, x.b, x.triangle) < std::tie(y.a, y.b, y.triangle);
  });
  g.edges_of.resize(m);
  std::vector<uint32_t> parent(m);
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::size_t begin = 0, end; begin < uses.size(); begin = end) {
    for (end = begin + 1; end < uses.size() && uses[end].a == uses[begin].a && uses[end].b == uses[begin].b; ++end) {
    }
    SurfaceFacets::Edge e{uses[begin].a, uses[begin].b, {}, true};
    for (std::size_t u = begin; u < end; ++u) {
      e.triangles.push_back(uses[u].triangle);
      g.edges_of[uses[u].triangle][uses[u].k] = static_cast<uint32_t>(g.edges.size());
    }
    if (mode == FacetMode::Coplanar && end - begin == 2 && same_facet(input, uses[begin], uses[begin + 1])) {
      e.ridge = false;
      parent[root(parent, uses[begin].triangle)] = root(parent, uses[begin + 1].triangle);
    }
    g.edges.push_back(std::move(e));
  }
  g.facet_of.assign(m, kNone);
  std::vector<uint32_t> facet_of_root(m, kNone);
  for (uint32_t j = 0; j < m; ++j) {
    uint32_t& f = facet_of_root[root(parent, j)];
    if (f == kNone) {
      f = static_cast<uint32_t>(g.triangles.size());
      g.triangles.emplace_back();
    }
    g.facet_of[j] = f;
    g.triangles[f].push_back(j);
  }
  return g;
}

}  // namespace sweepcdt::detail
