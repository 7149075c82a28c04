// EditableCdt: a PLC and its CDT kept in step while vertices are deleted (paper §5).
//
//   Plc<3> refined;
//   Triangulation<3> tri = cdt(plc, options, &refined);
//   EditableCdt<3> mesh(std::move(refined), std::move(tri));
//   mesh.remove_vertex(17);                  // throws NoCdtError (mesh unchanged) if no CDT remains
//   EditableCdt<3>::Snapshot now = mesh.snapshot();  // the PLC and CDT without vertex 17
//
// Deleting v empties its star, the simplices holding it, and fills the cavity with the CDT of the
// polytope its link bounds — star-shaped from v — by star_cdt()'s inward sweep (star_cdt.h): time
// O(star size · log). A vertex may lie
//   - inside the domain;
//   - on the boundary of a convex-hull domain (paper §5: the sweep "works correctly even if v lies
//     on the boundary"; the centre is perturbed away from a point inside the hull left, so that new
//     hull faces through v are built from inside; the new hull is checked to be convex);
//   - on constraining simplices, when each group of exactly coplanar ones around it (a sheet of a
//     facet; when the PLC has tags, only simplices with equal tags form one facet — cdt() tags a
//     refined PLC's triangles with their input triangle or coplanar facet) has v inside it (any D), or, for D = 3, on a straight edge of it with its two
//     neighbours along that edge (a Steiner point on a segment): the facet without v is then
//     triangulated anew by the (D-1)-dimensional star CDT of the hole (the paper's recursion),
//     computed on the facet's projection onto a coordinate hyperplane — exactly the facet's own
//     CDT when the facet is parallel to that hyperplane, a valid triangulation of it otherwise;
//   - (D = 3, asked for by unbend_facets_at_steiner_points) a Steiner point of cdt() that rounding
//     put off its segment or facet: a corner of facets bent by rounding, filled as if it had never
//     been made.
// Deleting a vertex can leave a PLC without a CDT (paper §5: the algorithm "may not behave in any
// reasonable manner" then). Every deletion is checked exactly before it is applied — the new
// simplices must tile the cavity (validate() of the cavity's CDT) and be locally Delaunay with
// their neighbours outside it, which with the rest of the CDT unchanged makes the whole a CDT — so
// such a deletion throws NoCdtError, with the vertex ids of the face concerned, and leaves the
// PLC and the CDT as they were.
//
// Vertex ids do not change while editing; snapshot() numbers the remaining ones anew, in the same
// order, so the perturbation order (§6, and tri.perturbation_rank) stays the same.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sweepcdt/cdt.h"

namespace sweepcdt {

// The vertex cannot leave the PLC: not a vertex of the triangulation, or a corner of a facet (it
// would change the facet's shape), or a case not implemented (a vertex on the boundary of a facet
// in D >= 4).
class VertexRemovalError : public Error {
 public:
  using Error::Error;
};

template <int D>
class EditableCdt {
 public:
  // `tri` must be a CDT of `plc` (as cdt(plc, options, &triangulated) returns it, with
  // `triangulated` as plc: Steiner points are points of the refined PLC); it is not checked again.
  EditableCdt(Plc<D> plc, Triangulation<D> tri);
  EditableCdt(EditableCdt&&) noexcept;
  EditableCdt& operator=(EditableCdt&&) noexcept;
  ~EditableCdt();

  // Deletes vertex v from the CDT and from the PLC. Throws NoCdtError (unchanged) when the PLC
  // without v has no CDT, VertexRemovalError (unchanged) when v cannot be deleted (above). Returns
  // what neighbours(v) returned before: a caller that reacts to a deletion's neighbours need not
  // walk every star twice (most attempts are refused).
  std::vector<uint32_t> remove_vertex(uint32_t v);

  // remove_vertex() in two steps, so that deletions can be worked out on several threads at once.
  // plan_removal(v) works out v's deletion — or the error it meets — without changing anything;
  // plans may be made concurrently, but never while a commit runs. commit_removal() applies a plan
  // (or throws its error, unchanged, as remove_vertex() would), after working it out again if a
  // commit since it was made changed a simplex it read. So plans committed in some order give
  // exactly what remove_vertex() in that order gives, whatever threads made them.
  class Removal {
   public:
    Removal();
    Removal(Removal&&) noexcept;
    Removal& operator=(Removal&&) noexcept;
    ~Removal();

   private:
    friend class EditableCdt;
    struct Plan;
    std::unique_ptr<Plan> plan_;
  };
  Removal plan_removal(uint32_t v) const;
  std::vector<uint32_t> commit_removal(Removal&& removal);
  // The same without throwing what a refused deletion met: false for NoCdtError and
  // VertexRemovalError (other errors are thrown), else true with the neighbours in `neighbours`. For
  // a caller that expects most deletions to be refused (unwinding costs as much as a small star).
  // Given `witness`, a refusal leaves there the NoCdtError's witness (its vertex ids: the simplex the
  // star sweep found in front of a face built after it, or, refused early, the merged segment's
  // ends and the three vertices that block it), empty for VertexRemovalError.
  bool try_commit_removal(Removal&& removal, std::vector<uint32_t>& neighbours, std::vector<uint32_t>* witness = nullptr);
  // Whether commit_removal() would use `removal` as it is (false for an empty one): no commit since
  // it was made changed what it read.
  bool plan_is_current(const Removal& removal) const;
  // Commits so far that had to work their plan out again (for tests and measurements).
  uint64_t plans_redone() const;
  // Deletions so far (remove_vertex, commit_removal, try_commit_removal) refused before their cavity
  // was built, while unbending: a Steiner point whose two pieces of a segment would merge into one
  // that is not Delaunay among the vertices of its star (guessed off its segment or in bent pieces:
  // guess_blocked_refusals), or one rounded off its segment whose star is too large to unbend (for
  // tests and measurements).
  uint64_t refused_early() const;

  // Steiner points of cdt() (Options::steiner) that rounding put a few ulps off their segment or
  // facet are corners of the refined PLC's facets, so they cannot go by default. With this on (D =
  // 3), and when the PLC's tags name the input facet each constraint is a piece of (cdt()'s refined
  // PLC before it maps them to the input's own tags), such a Steiner point — an id from
  // tri.num_input_points on — can: its facet's pieces around it are filled anew as if it had never
  // been made (sheets.h), under the same exact checks. What is left is a PLC whose facets are the
  // input's, split at the remaining points, as refinement would have made it without this point.
  // Only while the point's star has at most `largest_star` simplices (0: off, the default): in
  // facets bent by rounding the predicates are exact on nearly coplanar points, and a star merged
  // from deleted neighbours costs many times a point's own (cdt()'s deletion pass uses 32:
  // core/src/edit/remove_steiner.h).
  void unbend_facets_at_steiner_points(std::size_t largest_star);
  // While unbending: per tag, whether every point of that input facet lies exactly in its plane (no
  // Steiner point of it was rounded off its segment or placed inside it: cdt()'s refinement knows),
  // so that its pieces around a point are flat without the exact orientation tests that would
  // otherwise say so (zero, the predicates' slowest answer) before each early refusal below. Tags
  // not listed are tested.
  void know_flat_facets(std::vector<char> flat_by_tag);
  // While unbending, a Steiner point exactly on its segment, its facets' pieces around it flat, is
  // refused before its cavity is built (NoCdtError) when the segment its deletion would leave is not
  // Delaunay among the vertices of its star: proven, the star CDT would find no CDT either. With this
  // on (off by default), so is a point rounded off its segment or in bent pieces with that segment
  // blocked alike (VertexRemovalError), where the test proves nothing but nearly always agrees with
  // the star CDT: a point refused wrongly stays, as one Steiner point more, and the CDT is still
  // checked exactly. cdt()'s deletion pass turns it on (core/src/edit/remove_steiner.h).
  void guess_blocked_refusals(bool on);
  // A deletion whose cavity's CDT has more than `factor` times the simplices of the vertex's star,
  // plus 8, is refused (VertexRemovalError) with this set (0: off, the default). The CDT of a flat
  // cavity can need quadratically many simplices (two long rows of points, as the star of a Steiner
  // point on a thin wall's long edge leaves: 1462 tetrahedra for a star of 88), so such a deletion
  // trades one vertex for a far larger, worse mesh. cdt()'s deletion pass uses 3
  // (core/src/edit/remove_steiner.h).
  void limit_growth(unsigned factor);

  bool has_vertex(uint32_t v) const;
  std::vector<uint32_t> neighbours(uint32_t v) const;  // the vertices of v's link (sharing a simplex with it)
  std::vector<uint32_t> constraint_neighbours(uint32_t v) const;  // those sharing a constraint with it, ascending
  std::size_t num_vertices() const;   // vertices left
  std::size_t num_simplices() const;

  struct Snapshot {
    Plc<D> plc;                     // the PLC now: constraints on deleted vertices replaced
    Triangulation<D> triangulation; // its CDT, neighbours and regions included
    std::vector<uint32_t> old_ids;  // per vertex of the snapshot: its id in the EditableCdt
  };
  Snapshot snapshot() const;
  // The same, the mesh given up for it (its arrays become the snapshot's; it is empty afterwards):
  // no second copy of a large mesh at the end of an edit (std::move(mesh).release()).
  Snapshot release() &&;

  // The PLC that remove_vertex(v) would leave — the facets through v triangulated anew as it does —
  // numbered as snapshot() would then number it. For callers that want to know more than
  // NoCdtError says, and as the tests' oracle: cdt() of it fails exactly when remove_vertex(v) does.
  // Throws VertexRemovalError as remove_vertex() does.
  Plc<D> plc_without(uint32_t v) const;

 private:
  struct Impl;
  static std::unique_ptr<typename Removal::Plan> take(Removal& removal);  // leaves it empty; throws if it was
  std::unique_ptr<Impl> impl_;
};

}  // namespace sweepcdt
