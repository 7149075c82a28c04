// Steiner points so that a CDT exists (issue 7, beyond the paper), and coplanar facets (D = 3).
//
// Shewchuk's CDT theorem: a PLC has a CDT when every segment is strongly Delaunay. Here the facets
// are the input triangles (or, with FacetMode::Coplanar, the polygons of exactly coplanar adjacent
// triangles) and the segments are their boundary edges. Under the lifting-map perturbation of §6
// the points are in general position for spheres, so "strongly Delaunay" becomes "an edge of the
// perturbed Delaunay triangulation of all points". Rounds:
//   1. the Delaunay triangulation of the current points (delaunay.h: incremental, the same unique
//      triangulation as the sweep sphere, kept between rounds; only segments near the new points
//      are looked up again);
//   2. every segment that is not one of its edges is split — at a power-of-two distance from its
//      end when exactly one end is an input vertex; between two Steiner points where the vertex
//      that encroaches it most projects onto it when a midpoint would not free it of that vertex
//      (refine.cpp: encroacher_projection); at its midpoint otherwise; each point computed
//      from the input segment's ends at its parameter along it (a point that would round onto an
//      existing one takes another t: steiner_point.h) (the concentric-shell
//      rule of Ruppert and Shewchuk: subsegments that meet at an input vertex end on common spheres
//      about it, so segments at a small angle do not split each other without end);
//      — and again, pass after pass, every segment that the last pass's new points made not
//      Delaunay, looked for only near the points the pass changed (DelaunayEdges::changed_points):
//      on a band of a tessellated sphere nested in another, each split makes the next diagonal not
//      Delaunay, some 260 passes in a row on hollow_sphere_fine;
//   3. the triangles holding a split segment are split at the new points (facet-interior edges are
//      not segments: they need not be Delaunay).
// When every segment is Delaunay, each facet is flipped to its own 2D CDT (facet_flips.h). Folds:
// a split point is computed in floating point (sweepcdt/steiner_point.h), so it lies on its segment
// only to within a few units of rounding, and the triangles of a facet that meet at an edge from it
// are then not exactly coplanar. Such an edge is a ridge of the refined PLC like a segment; when it
// is not Delaunay it is flipped to the other diagonal of its quadrilateral if that one is Delaunay
// (facet_flips.h), else its midpoint becomes a point inside the facet and the rounds go on; the
// facet's next 2D CDT connects it to what it sees. Non-Delaunay folds are mostly fans of long thin
// triangles across a large facet (an input vertex facing a finely split segment, on CAD parts whose
// coordinates carry rounding noise), so such points are placed longest fold first and kept half
// their fold's length apart within a round, and a point that would encroach on a segment (lie in
// its diametral ball) splits that segment instead — Ruppert's graded refinement, restricted to the
// facets' folds. (Making such folds segments, as before, refined facets uniformly: pipe_tee_fine.stl
// and gearwheel_ascii.stl ran past the point budget.) When no fold gets a point, the folds become
// segments as a last resort. The shell distance is rounded to 20 significant bits of the piece
// split, points are made from the input segment's ends (sweepcdt/steiner_point.h), and where such a
// point would still round off its segment (coordinates near 0 beside large ones) its t moves by at
// most a 512th of the piece to where it comes out exact (refine.cpp: parameter_exactly_on), so on
// surfaces with float coordinates the points lie exactly on their segments and make no folds.
// So at the end every ridge — segment or fold — is Delaunay, and the theorem's premise holds
// exactly for the refined PLC as computed; cdt() triangulates it with the sweep and validates it.
// Lazy refinement (cdt.cpp, on float surfaces) asks for less: only the pieces of the required input
// segments, and, from its second attempt with points on (Refinement), of the segments that were
// Delaunay until that attempt's points broke them; the rest stay as they are, and the cavity sweep
// decides exactly whether the result has a CDT; its attempts leave folds as they are without even
// looking for them (Folds::NotLookedFor). Folds::LeftAsTheyAre (cdt.cpp: the first refinement of
// every segment, for every algorithm) likewise stops once the segments are Delaunay and the facets
// flipped: the folds that are still not Delaunay get no points, only counted, and the algorithm
// decides whether the CDT needs them.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "../delaunay/delaunay.h"
#include "edge_set.h"
#include "sweepcdt/cdt.h"

namespace sweepcdt::detail {

struct RefinedPlc {
  Plc<3> plc;                         // the input's points first, then the Steiner points
  uint32_t num_input_points = 0;
  std::vector<uint32_t> steiner_on;   // per Steiner point: an input triangle (index) holding it
  std::vector<uint32_t> original;     // per refined triangle: the input triangle it lies in (with
                                      // coplanar facets: the facet's first input triangle)
  // Per Steiner point: the two points it is a rounded split of (sweepcdt/steiner_point.h), which
  // `sweepcdt check` recognises it by: its input segment's ends (their difference exact), else the
  // ends of the piece it split, or a fold's two points.
  std::vector<std::array<uint32_t, 2>> made_from;
  // Per Steiner point: the input segment it lies on (its ends, the smaller id first), or kNone twice
  // for a point inside a facet.
  std::vector<std::array<uint32_t, 2>> on_segment;
  uint64_t rounds = 0, facets = 0, flips = 0;
  uint64_t folds_left = 0;  // folds not Delaunay left as they are (Folds::LeftAsTheyAre)
  // Per refined triangle: its facet holds a Steiner point rounded off its input segment, or one
  // inside the facet, so it may differ from the input's facet by rounding (refined_check.h).
  std::vector<char> off_input;
  // The Delaunay tetrahedralization of plc.points that refinement kept (SteinerMode::Auto), which
  // the cavity sweep starts from (cavity/cavity_cdt.h) instead of computing it again.
  std::optional<DelaunayMesh> delaunay;
  // Refinement started from the tetrahedralization the importer computed beside its check
  // (kept_tetrahedralization.h: claimed when refinement starts, waited for once it is needed).
  bool tetrahedralization_recorded = false;
};

// Input segments (edge_key of their ends) whose pieces must be Delaunay; the others are left as they
// are. Lazy refinement (cdt.cpp) starts with none and adds those of the cavities that find no CDT.
using RequiredSegments = EdgeSet;

// What becomes of the folds that are not Delaunay once the segments are: points inside their facets
// until they are (the theorem's premise), or nothing (a CDT may well exist all the same), counted in
// RefinedPlc::folds_left or not looked for at all — lazy refinement's attempts (Refinement), where
// the cavity sweep decides and nothing reads the count: looking for them mapped every facet edge
// each round (236 of perforated_tube_std's 8456 samples).
enum class Folds { MadeDelaunay, LeftAsTheyAre, NotLookedFor };

// A pass of refinement that adds at least this many points inserts them into the Delaunay
// tetrahedralization on a helper thread, given one, while the calling thread splits (and flips) the
// surface's triangles; the refined PLC is the same either way. (Not tuned: starting a thread costs
// tens of microseconds, 256 insertions some milliseconds.)
inline constexpr std::size_t kPointsBeside = 256;

// With SteinerMode::None only the facets are re-triangulated (FacetMode::Coplanar). `required`: only
// those input segments are split (and the folds and segments that points inside facets need); null:
// every segment, so that the refined PLC has a CDT by the theorem (with Folds::MadeDelaunay).
// Refinement starts from the tetrahedralization the importer kept in input's check record, if any
// and not taken yet; the result is the same either way.
RefinedPlc refine(const Plc<3>& input, const Options& options, const RequiredSegments* required = nullptr,
                  Folds folds = Folds::MadeDelaunay);

// Lazy refinement's attempts (cdt.cpp), each with more segments required than the last, folds left
// as they are. An attempt continues the last one's refinement — its points, facets and Delaunay
// tetrahedralization — and splits only the pieces of the segments required since (and those its
// points break), instead of refining from the input again: on a 175k-triangle marching-tetrahedra
// surface the third attempt refined from scratch for 5 s to add 552 points to the second's 107973.
// The points may differ from a refinement from scratch with the same segments required (they were
// split in another order); each attempt's PLC is decided exactly by the cavity sweep all the same.
// Holds the tetrahedralization of the input points until the first attempt that adds points: destroy
// it as soon as it is not needed.
class Refinement {
 public:
  // `required` must outlive this object; the caller adds to it between calls of next().
  Refinement(const Plc<3>& input, const Options& options, const RequiredSegments& required);
  ~Refinement();
  Refinement(const Refinement&) = delete;
  Refinement& operator=(const Refinement&) = delete;
  // The refined PLC with the pieces of every segment required now Delaunay (the first call: as
  // refine(input, options, &required, Folds::NotLookedFor)). `last`: what the last call returned,
  // or nothing on the first; its points and triangles are taken back (between attempts only what
  // cannot be made from them again is kept: refine.cpp, Refiner::set_aside).
  RefinedPlc next(RefinedPlc&& last);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sweepcdt::detail
