// Incremental Delaunay triangulation (Bowyer–Watson) in dimension D = 2..5 under the lifting-map
// perturbation of paper §6: the same unique triangulation the sweep sphere builds for a point set
// without constraints, but in O(n log n) expected time (for points spread evenly). The cavity sweep
// (cavity/cavity_cdt.h) starts from it in every dimension; Steiner refinement (steiner/refine.cpp)
// keeps the 3D one between its rounds (DelaunayEdges).
//
// Every geometric decision is an exact predicate (predicates::orient<D>, insphere_perturbed<D>);
// floating point only chooses the insertion order (a BRIO of Hilbert-sorted rounds) and the walk's
// random face order, neither of which can change the result: the perturbed Delaunay triangulation
// is unique.
//
// The convex hull is handled with an infinite vertex: every hull facet f carries a ghost simplex
// (f, oo). A new point p conflicts with it when p lies strictly outside f, or in the hyperplane of f
// and inside the perturbed circumsphere of f within it. The latter is decided as the insphere test of
// the finite simplex s behind f (see facet_flips.h: the cofactor of s's vertex off f is orient(f, p)
// = 0, so that vertex is never the decisive one of the perturbation), which makes the ghost and its
// finite neighbour agree for p in the hyperplane, so no flat simplex is ever created.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace sweepcdt::detail {

// Simplices (D + 1 point ids each, positively oriented: predicates::orient<D> > 0) of the perturbed
// Delaunay triangulation of the points (n x D doubles), covering their convex hull.
// Requires at least D + 1 affinely independent points; throws sweepcdt::Error otherwise, and for
// duplicate or non-finite points.
template <int D>
std::vector<std::array<uint32_t, D + 1>> delaunay_simplices(const std::vector<double>& points);

// The same triangulation with its adjacency, in Triangulation's encoding (sweepcdt/triangulation.h):
// `tets` D + 1 point ids per simplex, positively oriented; `neighbors` per facet i of simplex t
// (opposite t's vertex i) (D + 1) u + j, facet j of simplex u, or kNone on the convex hull.
// (The name says tetrahedra: D = 3 is the common case.)
// `inserted`, when given, is called with the number of points inserted so far every 1024 insertions;
// it may throw (to cancel).
struct DelaunayMesh {
  std::vector<uint32_t> tets;
  std::vector<uint32_t> neighbors;
};
template <int D>
DelaunayMesh delaunay_mesh(const std::vector<double>& points, const std::function<void(std::size_t)>& inserted = {});

// The same triangulation, inserting the points in the given order (a permutation of 0..n-1) instead
// of the spatial order. For tests: the result must not depend on the order.
template <int D>
std::vector<std::array<uint32_t, D + 1>> delaunay_simplices_in_order(const std::vector<double>& points,
                                                                     const std::vector<uint32_t>& order);

// The 3D triangulation kept between Steiner rounds: points appended to the caller's vector are
// inserted, and edges looked up, without rebuilding it (refine.cpp asks once per segment per round).
class DelaunayEdges {
 public:
  // Triangulates `points`, which must outlive this object; same requirements as above. `inserted`
  // as for delaunay_mesh (it may throw to cancel).
  explicit DelaunayEdges(const std::vector<double>& points, const std::function<void(std::size_t)>& inserted = {});
  // The same from `mesh`, the Delaunay triangulation of `points` as mesh() gives it (refine.cpp: a
  // refinement made again takes the one its last attempt handed out), without computing it again;
  // null when some point is no vertex of it (then it is not that triangulation).
  static std::unique_ptr<DelaunayEdges> from_mesh(const std::vector<double>& points, const DelaunayMesh& mesh);
  ~DelaunayEdges();
  // Reads the points from `points` from now on: a copy of the vector given so far, or a longer one
  // that starts with its points (it must outlive this object).
  void rebind(const std::vector<double>& points);
  // Inserts the points appended to `points` since the last call (or the construction), if any.
  // `near(id)`, when given: a point near new point `id` (kNone, or one not inserted yet: none), where
  // its location starts. The triangulation is the same either way; only the walk is shorter.
  void insert_new_points(const std::function<uint32_t(uint32_t)>& near = {});
  // Whether ab is an edge of the triangulation (a and b inserted points).
  bool has_edge(uint32_t a, uint32_t b);
  // The vertices sharing a tetrahedron with a (with repeats).
  void link_vertices(uint32_t a, std::vector<uint32_t>& out);
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
  DelaunayEdges() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sweepcdt::detail
