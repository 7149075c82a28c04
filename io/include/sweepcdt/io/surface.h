// From a soup to a validated surface: welding, then every check that decides whether the triangles
// bound a volume, then the orientation each shell needs (paper §1: a facet-bounded PLC notates which
// side of each facet is exterior).
//
//   Soup ──weld()──► Surface ──inspect()──► SurfaceReport ──to_plc() (to_plc.h)──► Plc<3>
//
// Everything is exact: welding merges exactly equal coordinates only (never a tolerance), and every
// geometric test goes through sweepcdt::predicates.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sweepcdt/io/error.h"
#include "sweepcdt/io/soup.h"
#include "sweepcdt/plc.h"

namespace sweepcdt::io {

// A soup whose points are distinct: triangle j is soup triangle j with welded point ids.
struct Surface {
  std::string file;
  Format format = Format::Off;
  uint64_t points_in_file = 0;  // before welding
  std::vector<double> points;   // n x 3, distinct, in order of first use by the soup's point ids
  std::vector<uint32_t> triangles;

  std::size_t num_points() const { return points.size() / 3; }
  std::size_t num_triangles() const { return triangles.size() / 3; }
};

// Merges points with exactly equal coordinates (STL, glTF and Draco store a triangle's corners
// separately). Points no triangle uses are dropped.
Surface weld(const Soup& soup);

// A connected component of triangles (connected through shared vertices).
struct Shell {
  uint32_t first_triangle = 0;  // smallest triangle index in it
  uint32_t triangles = 0;
  bool closed = false;          // every edge of it has exactly two triangles of the whole surface
  // Filled only when the whole surface is valid (SurfaceReport::valid()):
  int32_t parent = -1;          // innermost shell that encloses it, or -1
  uint32_t depth = 0;           // number of shells that enclose it: even = outer boundary of a body,
                                // odd = boundary of a cavity
  bool reversed = false;        // its triangles were oriented against its depth and were flipped
};

struct SurfaceReport {
  std::string file;
  Format format = Format::Off;
  uint64_t triangles = 0;
  uint64_t points_in_file = 0;
  uint64_t points = 0;  // after welding

  // Problems: first ones of each kind (up to the limit given to inspect()); counts of all.
  std::vector<SurfaceProblem> problems;
  std::array<uint64_t, kSurfaceProblemKinds> counts{};
  uint64_t count(SurfaceProblemKind kind) const { return counts[static_cast<int>(kind)]; }

  bool closed = false;    // no boundary edge, no non-manifold edge, no triangle naming a vertex twice
  bool manifold = false;  // no non-manifold edge or vertex
  bool oriented = false;  // every two-triangle edge is traversed in opposite directions in the input
  bool self_intersections_checked = false;  // false when the input was too broken to look

  std::vector<Shell> shells;
  uint64_t reversed_triangles = 0;  // triangles whose orientation to_plc() reverses (the repair)
  std::vector<uint8_t> reverse;     // per triangle, 1 if to_plc() reverses it (valid surfaces only)

  std::array<double, 3> box_min{}, box_max{};

  // When the self-intersection test found nothing: core's record that the PLC of the surface's points
  // and triangles passed find_problems(). to_plc() hands it on (Plc::checked), so that cdt() does not
  // repeat the exact intersection tests; core compares it with the PLC in full before relying on it.
  std::shared_ptr<const PlcCheck<3>> checked;

  uint64_t closed_shells() const;
  uint64_t nested_shells() const;  // shells with depth > 0
  // A closed, manifold, orientable surface without degenerate, duplicate or intersecting triangles.
  bool valid() const;
  // Throws SurfaceError listing the problems unless valid().
  void throw_if_invalid() const;
};

// Checks the surface; reports at most `limit_per_kind` problems of each kind (all are counted).
// Exact self-intersection tests use core's find_problems (a box tree over the triangles).
// `before_cdt`: the surface is about to be meshed (plc_of_soup, import_plc): given a second thread,
// the Delaunay tetrahedralization of its points is computed there beside the self-intersection tests
// and kept in `checked` for cdt() (core's find_problems_before_cdt).
SurfaceReport inspect(const Surface& surface, std::size_t limit_per_kind = 10, bool before_cdt = false);

}  // namespace sweepcdt::io
