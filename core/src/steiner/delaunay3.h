// Incremental 3D Delaunay triangulation (Bowyer–Watson) under the lifting-map perturbation of paper
// §6: the same unique triangulation the sweep sphere builds for a point set without constraints, but
// in O(n log n) expected time. Steiner refinement (refine.cpp) needs it once per round.
//
// Every geometric decision is an exact predicate (predicates::orient<3>, insphere_perturbed<3>);
// floating point only chooses the insertion order (a BRIO of Hilbert-sorted rounds) and the walk's
// random face order, neither of which can change the result: the perturbed Delaunay triangulation
// is unique.
//
// The convex hull is handled with an infinite vertex: every hull triangle abc carries a ghost
// tetrahedron (a, b, c, oo). A new point p conflicts with it when p lies strictly outside abc, or in
// the plane of abc and inside the perturbed circumcircle of abc. The latter is decided as the
// insphere test of the finite tetrahedron abcd behind abc (see facet_flips.h: d's cofactor is
// orient(a, b, c, p) = 0, so d is never the decisive vertex of the perturbation), which makes the
// ghost and its finite neighbour agree for coplanar p, so no flat tetrahedron is ever created.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace sweepcdt::detail {

// Tetrahedra (4 point ids each, positively oriented: predicates::orient<3> > 0) of the perturbed
// Delaunay triangulation of the points (n x 3 doubles), covering their convex hull.
// Requires at least 4 affinely independent points; throws sweepcdt::Error otherwise, and for
// duplicate or non-finite points.
std::vector<std::array<uint32_t, 4>> delaunay_tetrahedra(const std::vector<double>& points);

// The same triangulation with its adjacency, in Triangulation's encoding (sweepcdt/triangulation.h):
// `tets` 4 point ids per tetrahedron, positively oriented; `neighbors` per facet i of tetrahedron t
// (opposite t's vertex i) 4 * u + j, facet j of tetrahedron u, or kNone on the convex hull.
// `inserted`, when given, is called with the number of points inserted so far every 1024 insertions;
// it may throw (to cancel).
struct DelaunayMesh {
  std::vector<uint32_t> tets;
  std::vector<uint32_t> neighbors;
};
DelaunayMesh delaunay_mesh(const std::vector<double>& points, const std::function<void(std::size_t)>& inserted = {});

// The same triangulation, inserting the points in the given order (a permutation of 0..n-1) instead
// of the spatial order. For tests: the result must not depend on the order.
std::vector<std::array<uint32_t, 4>> delaunay_tetrahedra_in_order(const std::vector<double>& points,
                                                                  const std::vector<uint32_t>& order);

// The same triangulation kept between Steiner rounds: points appended to the caller's vector are
// inserted, and edges looked up, without rebuilding it (refine.cpp asks once per segment per round).
class DelaunayEdges {
 public:
  // Triangulates `points`, which must outlive this object; same requirements as above. `inserted`
  // as for delaunay_mesh (it may throw to cancel).
  explicit DelaunayEdges(const std::vector<double>& points, const std::function<void(std::size_t)>& inserted = {});
  ~DelaunayEdges();
  // Inserts the points appended to `points` since the last call (or the construction), if any.
  void insert_new_points();
  // Whether ab is an edge of the triangulation (a and b inserted points).
  bool has_edge(uint32_t a, uint32_t b);
  // False when ab is an edge exactly when it was before the last insert_new_points: neither end is
  // new and some end lost no tetrahedron (every new edge has a new end). All true after construction.
  bool may_have_changed(uint32_t a, uint32_t b) const;
  // The points the last insert_new_points inserted or took a tetrahedron from (all after
  // construction), each once: every pair that may_have_changed has an end among them, so a caller
  // can look at the edges near a change without scanning all of its own.
  const std::vector<uint32_t>& changed_points() const;
  // The triangulation as it is (points inserted so far) with its adjacency.
  DelaunayMesh mesh() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sweepcdt::detail
