// The facets' Lawson flips (steiner/facet_flips.h) end at each flat facet's 2D CDT from whatever
// triangulation refinement hands them. Checked against the 2D CDT that cdt<2>() builds with the
// sweep (an independent algorithm) on the same points.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include "delaunay/delaunay.h"
#include "steiner/facet_flips.h"
#include "steiner/facet_groups.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/predicates/orientation.h"

using namespace sweepcdt;

namespace {

using Triangle = std::array<uint32_t, 3>;

// A long thin triangle a b c in the plane z = 0 with k points on each of its edges (evenly spaced), triangulated
// the way refinement splits it (steiner/refine.cpp: each split point joined to the opposite
// vertex): a fan from c to the points of ab, then fans to the points of bc and ca from the
// triangles holding those edges. Far from its CDT: the fan's long edges cross the CDT's strip of
// short ones, and Lawson's flips take about k^2 / 2 of them.
struct FannedFacet {
  std::vector<double> points;  // n x 3
  std::vector<Triangle> triangles;
  detail::EdgeSet segments;
  std::vector<std::array<uint32_t, 2>> on_segment;

  explicit FannedFacet(uint32_t k) {
    add({0, 0}, {kNone, kNone});     // a = 0
    add({4096, 0}, {kNone, kNone});  // b = 1
    add({2048, 3}, {kNone, kNone});  // c = 2: the facet is 4096 long and 3 high
    const auto edge_points = [&](uint32_t u, uint32_t v) {
      std::vector<uint32_t> ids{u};
      for (uint32_t i = 1; i <= k; ++i) {
        const double t = static_cast<double>(i) / (k + 1);
        add({points[3 * u] + t * (points[3 * v] - points[3 * u]), points[3 * u + 1] + t * (points[3 * v + 1] - points[3 * u + 1])},
            {std::min(u, v), std::max(u, v)});
        ids.push_back(static_cast<uint32_t>(points.size() / 3 - 1));
      }
      ids.push_back(v);
      for (std::size_t i = 0; i + 1 < ids.size(); ++i) segments.insert(detail::edge_key(ids[i], ids[i + 1]));
      return ids;
    };
    const std::vector<uint32_t> ab = edge_points(0, 1), bc = edge_points(1, 2), ca = edge_points(2, 0);
    // The fan from c over ab; its last triangle (m, b, c) takes the fan over bc from m, its first
    // (a, m', c) the fan over ca from m'.
    for (std::size_t i = 1; i + 2 < ab.size(); ++i) triangles.push_back({ab[i], ab[i + 1], 2});
    for (std::size_t i = 0; i + 1 < bc.size(); ++i) triangles.push_back({ab[ab.size() - 2], bc[i], bc[i + 1]});
    for (std::size_t i = 0; i + 1 < ca.size(); ++i) triangles.push_back({ab[1], ca[i], ca[i + 1]});
  }

  void add(std::array<double, 2> xy, std::array<uint32_t, 2> segment) {
    for (const double x : {xy[0], xy[1], 0.0}) points.push_back(x);  // (insert of a list: GCC 12's false -Wstringop-overflow)
    on_segment.push_back(segment);
  }
};

std::set<Triangle> canonical(const std::vector<Triangle>& triangles) {
  std::set<Triangle> result;
  for (Triangle t : triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    result.insert(t);
  }
  return result;
}

// The 2D CDT of the facet's points with its boundary pieces as segments (the domain is the
// convex hull, the big triangle), oriented counterclockwise as the facet is.
std::set<Triangle> cdt_2d(const FannedFacet& facet) {
  Plc<2> plc;
  for (std::size_t i = 0; i < facet.points.size(); i += 3) plc.points.insert(plc.points.end(), {facet.points[i], facet.points[i + 1]});
  for (const uint64_t key : facet.segments) plc.simplices.insert(plc.simplices.end(), {static_cast<uint32_t>(key >> 32), static_cast<uint32_t>(key)});
  const Triangulation<2> t = cdt(plc);
  std::vector<Triangle> triangles;
  for (std::size_t j = 0; j < t.num_simplices(); ++j) {
    const uint32_t* s = t.simplex(j);
    const bool ccw = predicates::orient<2>({t.point(s[0]), t.point(s[1]), t.point(s[2])}) == predicates::Sign::Positive;
    triangles.push_back(ccw ? Triangle{s[0], s[1], s[2]} : Triangle{s[0], s[2], s[1]});
  }
  return canonical(triangles);
}

}  // namespace

// The fan needs more flips than the cap that used to stop them (10 per triangle + 1000, meant for
// facets flat only to within rounding): stopped there, the facet kept long edges that are not in
// its CDT, and the refined PLC had no CDT (pipe_tee_std.stl when its splits came in another order).
TEST(FacetFlips, FanOfAThinFacetReachesItsCdtPastTheRoundingCap) {
  for (const uint32_t k : {3u, 31u, 511u}) {  // k + 1 a power of two: the points lie exactly on the edges
    FannedFacet facet(k);
    const std::set<Triangle> expected = cdt_2d(facet);
    ASSERT_EQ(expected.size(), facet.triangles.size()) << k;
    const uint64_t flips = detail::flip_facets_to_cdt({facet.points, facet.triangles, facet.segments, facet.on_segment});
    EXPECT_EQ(canonical(facet.triangles), expected) << k << " points per edge, " << flips << " flips";
    if (k == 511) EXPECT_GT(flips, 10 * facet.triangles.size() + 1000) << "the case no longer needs more flips than the old cap";
  }
}

// Folds (steiner/facet_flips.h): a flip across a fold is tried only where a point of its
// quadrilateral is marked bent, since four points in their facet's plane make no fold. The flips
// must be those of trying every quadrilateral. A jittered grid in the plane z = 0, each cell split
// by its diagonal that is not Delaunay, every third point lifted off the plane (as rounding lifts
// Steiner points) and marked bent, between two walls of points that its folds must be Delaunay
// against (a thin part), against every point marked bent.
TEST(FacetFlips, FoldsFlipAsIfEveryPointWereBent) {
  constexpr uint32_t n = 12;
  std::vector<double> points;
  std::vector<char> lifted;
  uint32_t state = 12345;
  const auto jitter = [&] {
    state = state * 1664525u + 1013904223u;
    return (static_cast<double>(state >> 8) / (1u << 24) - 0.5) * 0.4;
  };
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = 0; j < n; ++j) {
      const bool inside = i > 0 && j > 0 && i + 1 < n && j + 1 < n;
      const bool lift = inside && (i * n + j) % 3 == 0;
      points.insert(points.end(), {i + (inside ? jitter() : 0.0), j + (inside ? jitter() : 0.0), lift ? ((i + j) % 2 ? 1 : -1) * 0x1p-20 : 0.0});
      lifted.push_back(lift);
    }
  const auto id = [&](uint32_t i, uint32_t j) { return i * n + j; };
  const auto xy = [&](uint32_t v) { return std::array<double, 2>{points[3 * v], points[3 * v + 1]}; };
  // Whether d lies inside the circle through a, b, c (counterclockwise): only to build the fans.
  const auto in_circle = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    const auto [ax, ay] = xy(a);
    const auto [bx, by] = xy(b);
    const auto [cx, cy] = xy(c);
    const auto [dx, dy] = xy(d);
    const double m[3][3] = {{ax - dx, ay - dy, (ax - dx) * (ax - dx) + (ay - dy) * (ay - dy)},
                            {bx - dx, by - dy, (bx - dx) * (bx - dx) + (by - dy) * (by - dy)},
                            {cx - dx, cy - dy, (cx - dx) * (cx - dx) + (cy - dy) * (cy - dy)}};
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]) > 0;
  };
  std::vector<Triangle> grid;
  detail::EdgeSet boundary;
  for (uint32_t i = 0; i + 1 < n; ++i)
    for (uint32_t j = 0; j + 1 < n; ++j) {
      const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);  // counterclockwise
      if (in_circle(a, b, c, d)) grid.insert(grid.end(), {Triangle{a, b, c}, Triangle{a, c, d}});  // ac is not Delaunay
      else grid.insert(grid.end(), {Triangle{a, b, d}, Triangle{b, c, d}});
    }
  for (uint32_t k = 0; k + 1 < n; ++k)
    for (const auto& [u, v] : {std::pair{id(k, 0), id(k + 1, 0)}, std::pair{id(k, n - 1), id(k + 1, n - 1)}, std::pair{id(0, k), id(0, k + 1)},
                               std::pair{id(n - 1, k), id(n - 1, k + 1)}})
      boundary.insert(detail::edge_key(u, v));
  // Two walls beside the facet (a thin part), which its folds must be Delaunay against.
  for (uint32_t v = 0; v < n * n; ++v)
    for (const double z : {-0.7, 0.7}) points.insert(points.end(), {points[3 * v] + 0.5, points[3 * v + 1] + 0.5, z});
  lifted.resize(points.size() / 3, 0);
  const std::vector<std::array<uint32_t, 2>> on_no_segment(lifted.size(), {kNone, kNone});
  detail::DelaunayEdges delaunay(points);
  const auto delaunay_edge = [&](uint32_t a, uint32_t b) { return delaunay.has_edge(a, b); };
  std::vector<Triangle> marked = grid, every = grid, none = grid;
  const uint64_t flips = detail::flip_folds_to_delaunay({points, marked, boundary, on_no_segment}, lifted, delaunay_edge);
  const uint64_t flips_every =
      detail::flip_folds_to_delaunay({points, every, boundary, on_no_segment}, std::vector<char>(lifted.size(), 1), delaunay_edge);
  ASSERT_GT(flips_every, 0u) << "no fold flipped: nothing exercised";
  EXPECT_EQ(flips, flips_every);
  EXPECT_EQ(marked, every);
  // Not a comparison that holds for any flips: with no point marked bent nothing flips.
  EXPECT_EQ(detail::flip_folds_to_delaunay({points, none, boundary, on_no_segment}, std::vector<char>(lifted.size(), 0), delaunay_edge), 0u);
  EXPECT_EQ(none, grid);
}
