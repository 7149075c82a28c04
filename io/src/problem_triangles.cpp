#include "sweepcdt/io/problem_triangles.h"

#include <algorithm>
#include <utility>

namespace sweepcdt::io {
namespace {

std::pair<uint64_t, uint64_t> edge_key(uint64_t a, uint64_t b) { return {std::min(a, b), std::max(a, b)}; }

}  // namespace

std::vector<uint32_t> problem_triangles(const Surface& surface, const SurfaceReport& report) {
  std::vector<uint32_t> out;
  std::vector<std::pair<uint64_t, uint64_t>> edges;  // (lo, hi) vertex ids
  std::vector<uint64_t> vertices;
  for (const SurfaceProblem& p : report.problems) {
    switch (p.kind) {
      case SurfaceProblemKind::BoundaryEdge:
      case SurfaceProblemKind::NonManifoldEdge:
        if (p.elements.size() == 2) edges.push_back(edge_key(p.elements[0], p.elements[1]));
        break;
      case SurfaceProblemKind::NonManifoldVertex:
        vertices.insert(vertices.end(), p.elements.begin(), p.elements.end());
        break;
      default:  // the elements are triangles
        for (uint64_t t : p.elements)
          if (t < surface.num_triangles()) out.push_back(static_cast<uint32_t>(t));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::sort(vertices.begin(), vertices.end());
  if (!edges.empty() || !vertices.empty()) {
    for (uint32_t t = 0; t < surface.num_triangles(); ++t) {
      const uint32_t* c = surface.triangles.data() + 3 * std::size_t{t};
      bool hit = false;
      for (int i = 0; i < 3 && !hit; ++i) {
        hit = std::binary_search(vertices.begin(), vertices.end(), uint64_t{c[i]}) ||
              std::binary_search(edges.begin(), edges.end(), edge_key(c[i], c[(i + 1) % 3]));
      }
      if (hit) out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<uint32_t> triangles_at_vertices(const Surface& surface, std::vector<uint32_t> vertices) {
  std::sort(vertices.begin(), vertices.end());
  std::vector<uint32_t> out;
  for (uint32_t t = 0; t < surface.num_triangles(); ++t) {
    const uint32_t* c = surface.triangles.data() + 3 * std::size_t{t};
    if (std::binary_search(vertices.begin(), vertices.end(), c[0]) || std::binary_search(vertices.begin(), vertices.end(), c[1]) ||
        std::binary_search(vertices.begin(), vertices.end(), c[2]))
      out.push_back(t);
  }
  return out;
}

}  // namespace sweepcdt::io
