// Internal: the facets of the input surface, as verify_cdt() (sweepcdt/verify_cdt.h) verifies a
// mesh against them under a FacetMode.
//
// The rule is the one `--facets` documents (FacetMode, sweepcdt/cdt.h), computed here from the
// input alone so that check does not share the code that made the mesh: with Triangles every input
// triangle is a facet; with Coplanar two triangles sharing an edge that no third triangle has are
// one facet when they are exactly coplanar (orient3d of one triangle and the other's third vertex
// is zero; the material is on the same side of both, see surface_facets.cpp). Facets are numbered
// in the order of their first (smallest) input triangle, which is the face id `mesh` gives all of
// a facet's triangles.
//
// Edges are the input's edges, each once. An edge is a ridge — on the boundary of every facet that
// has it — unless it joins the two triangles of one facet. Ridges are the segments that `--steiner
// auto` splits.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

struct SurfaceFacets {
  struct Edge {
    uint32_t a, b;                    // input vertex ids, a < b
    std::vector<uint32_t> triangles;  // the input triangles that have it, ascending
    bool ridge = true;
  };
  FacetMode mode = FacetMode::Triangles;
  std::vector<Edge> edges;
  std::vector<std::array<uint32_t, 3>> edges_of;  // per input triangle (v0 v1 v2): edges v0v1, v1v2, v2v0
  std::vector<uint32_t> facet_of;                 // per input triangle
  std::vector<std::vector<uint32_t>> triangles;   // per facet: its input triangles, ascending

  std::size_t num_facets() const { return triangles.size(); }
  uint32_t first_triangle(uint32_t facet) const { return triangles[facet].front(); }
  // "input triangle 7 (3 4 9)", or "the coplanar facet of input triangles 7, 8, 12 (3 triangles)".
  std::string name(uint32_t facet, const Plc<3>& input) const;
};

SurfaceFacets group_surface_facets(const Plc<3>& input, FacetMode mode);

// Input triangle j's vertices ordered so that the material is on its positive side (exterior
// notation Negative keeps the input's order).
std::array<uint32_t, 3> material_positive(const Plc<3>& input, uint32_t j);

}  // namespace sweepcdt::detail
