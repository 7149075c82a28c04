#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "refined_check.h"
#include "sweepcdt/error.h"
#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"
#include "test_shapes.h"

using namespace sweepcdt;
using fixtures::grid_box_surface;
using fixtures::unit_cube_surface;

namespace {

template <int D>
std::vector<PlcProblemKind> kinds(const Plc<D>& plc) {
  std::vector<PlcProblemKind> k;
  for (const auto& p : find_problems(plc)) k.push_back(p.kind);
  return k;
}

template <int D>
bool has(const Plc<D>& plc, PlcProblemKind kind, std::vector<uint64_t> elements = {}) {
  for (const auto& p : find_problems(plc))
    if (p.kind == kind && (elements.empty() || p.elements == elements)) return true;
  return false;
}

TEST(PlcCheck, ValidCubeSurfacePasses) {
  const Plc<3> cube = unit_cube_surface();
  EXPECT_TRUE(find_problems(cube).empty());
  EXPECT_NO_THROW(check(cube));
  EXPECT_TRUE(cube.facet_bounded());
}

// The record of a check (Plc::checked) only ever saves time: find_problems() answers the same with it.
TEST(PlcCheck, RecordOnlyForAProblemFreePlcAndOnlyWhereItCovers) {
  Plc<3> cube = grid_box_surface(2);
  std::shared_ptr<const PlcCheck<3>> record;
  EXPECT_TRUE(find_problems(cube, 10, nullptr, &record).empty());
  ASSERT_TRUE(record);
  EXPECT_TRUE(record->covers(cube));

  // A problem: no record (and an old one is reset).
  Plc<3> bad = cube;
  bad.simplices[3 * 0 + 1] = bad.simplices[3 * 0];  // a repeated vertex
  std::shared_ptr<const PlcCheck<3>> none = record;
  EXPECT_FALSE(find_problems(bad, 10, nullptr, &none).empty());
  EXPECT_FALSE(none);

  // The record travels with copies; any change to points or simplices makes it not cover.
  Plc<3> copy = cube;
  copy.checked = record;
  EXPECT_TRUE(find_problems(copy).empty());
  Plc<3> moved = copy;
  moved.points[3 * 7 + 2] = -0.0 == moved.points[3 * 7 + 2] ? 0.0 : -0.0;  // a different bit pattern
  EXPECT_FALSE(record->covers(moved));
  Plc<3> crossing = copy;  // a vertex pushed through the opposite face: intersections
  for (int k = 0; k < 3; ++k) crossing.points[3 * 0 + k] = 3.0;
  EXPECT_FALSE(record->covers(crossing));
  EXPECT_TRUE(has(crossing, PlcProblemKind::Intersection));
  Plc<3> renumbered = copy;
  std::swap(renumbered.simplices[0], renumbered.simplices[1]);
  EXPECT_FALSE(record->covers(renumbered));

  // What the record does not cover is checked as always.
  Plc<3> shapes = copy;
  shapes.exterior.pop_back();
  EXPECT_TRUE(has(shapes, PlcProblemKind::BadShape));
  Plc<3> seeds = copy;
  seeds.region_seeds.push_back({{NAN, 0.0, 0.0}, 1});
  EXPECT_TRUE(has(seeds, PlcProblemKind::BadRegionSeed));
}

TEST(PlcCheck, ShapeErrorsStopBeforeGeometry) {
  Plc<3> plc = unit_cube_surface();
  plc.points.pop_back();
  EXPECT_TRUE(has(plc, PlcProblemKind::BadShape));
  plc = unit_cube_surface();
  plc.exterior.pop_back();
  EXPECT_TRUE(has(plc, PlcProblemKind::BadShape));
}

TEST(PlcCheck, NonFiniteAndRangeAndRepeats) {
  Plc<3> plc = unit_cube_surface();
  plc.points[3 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(has(plc, PlcProblemKind::NonFinitePoint, {5}));
  plc = unit_cube_surface();
  plc.points[0] = INFINITY;
  EXPECT_TRUE(has(plc, PlcProblemKind::NonFinitePoint, {0}));
  plc = unit_cube_surface();
  plc.simplices[3 * 7 + 2] = 99;
  EXPECT_TRUE(has(plc, PlcProblemKind::IndexOutOfRange, {7}));
  plc = unit_cube_surface();
  plc.simplices[3 * 4 + 1] = plc.simplices[3 * 4];
  EXPECT_TRUE(has(plc, PlcProblemKind::RepeatedVertex, {4}));
  EXPECT_THROW(check(plc), PlcError);
}

TEST(PlcCheck, DuplicatePointsNamed) {
  Plc<3> plc = unit_cube_surface();
  plc.points.insert(plc.points.end(), {1, 1, 0});  // equal to point 3
  EXPECT_TRUE(has(plc, PlcProblemKind::DuplicatePoints, {3, 8}));
}

TEST(PlcCheck, DegenerateAndDuplicateSimplices) {
  Plc<3> plc = unit_cube_surface();
  plc.points.insert(plc.points.end(), {2, 2, 2, 3, 3, 3});  // 8, 9 collinear with 7 = (1,1,1)
  plc.simplices.insert(plc.simplices.end(), {7, 8, 9});
  plc.exterior.push_back(ExteriorSide::None);
  EXPECT_TRUE(has(plc, PlcProblemKind::DegenerateSimplex, {12}));

  plc = unit_cube_surface();
  plc.simplices.insert(plc.simplices.end(), {3, 0, 2});  // simplex 0 again, other order
  plc.exterior.push_back(ExteriorSide::None);
  EXPECT_TRUE(has(plc, PlcProblemKind::DuplicateSimplex, {0, 12}));
}

TEST(PlcCheck, PiercingTriangleIsAnIntersection) {
  Plc<3> plc = unit_cube_surface();
  // A triangle through the top face (z = 1) and far outside.
  plc.points.insert(plc.points.end(), {0.5, 0.4, 0.5, 0.5, 0.6, 0.5, 0.5, 0.5, 3});
  plc.simplices.insert(plc.simplices.end(), {8, 9, 10});
  plc.exterior.push_back(ExteriorSide::None);
  const auto problems = find_problems(plc);
  ASSERT_FALSE(problems.empty());
  for (const auto& p : problems) {
    EXPECT_EQ(p.kind, PlcProblemKind::Intersection);
    EXPECT_EQ(p.elements.back(), 12u);
  }
}

TEST(PlcCheck, CoplanarOverlapSharingAnEdge) {
  Plc<3> plc;
  plc.points = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 1, 0};
  plc.simplices = {0, 1, 2, 0, 1, 3};  // 3 lies inside triangle 0: same side of edge 01
  EXPECT_TRUE(has(plc, PlcProblemKind::Intersection, {0, 1}));
  plc.points[10] = -1;  // now on the other side: a proper shared edge
  EXPECT_TRUE(find_problems(plc).empty());
}

TEST(PlcCheck, SharedVertexWithOverlappingEdgeRay) {
  Plc<3> plc;
  // Triangles sharing vertex 0 whose edges 0-1 and 0-3 point the same way: they overlap on a segment.
  plc.points = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 0, 0, 0, 0, 5};
  plc.simplices = {0, 1, 2, 0, 3, 4};
  EXPECT_TRUE(has(plc, PlcProblemKind::Intersection, {0, 1}));
  plc.points[9] = -1;  // opposite direction: they meet only at vertex 0
  EXPECT_TRUE(find_problems(plc).empty());
}

TEST(PlcCheck, IsolatedPointOnAFace) {
  Plc<3> plc = unit_cube_surface();
  plc.points.insert(plc.points.end(), {0.25, 0.5, 0});  // inside triangle (0, 2, 3) of the bottom face
  EXPECT_TRUE(has(plc, PlcProblemKind::PointOnSimplex, {8, 0}));
  plc.points.back() = -0.5;  // below the cube: fine
  EXPECT_TRUE(find_problems(plc).empty());
}

TEST(PlcCheck, GridBoxWithManyCoplanarTrianglesPasses) {
  const Plc<3> box = grid_box_surface(30);  // 10800 triangles
  EXPECT_EQ(box.num_simplices(), 10800u);
  EXPECT_TRUE(find_problems(box).empty());
}

TEST(PlcCheck, DentThroughTheBoxIsFound) {
  Plc<3> box = grid_box_surface(8);
  // Push a vertex of the top face (z = 8) below the bottom face: its triangles pierce the bottom.
  for (std::size_t i = 0; i < box.num_points(); ++i)
    if (box.points[3 * i] == 4 && box.points[3 * i + 1] == 4 && box.points[3 * i + 2] == 8) box.points[3 * i + 2] = -1;
  uint64_t total = 0;
  const auto problems = find_problems(box, 10, &total);
  EXPECT_GT(total, 0u);
  for (const auto& p : problems) EXPECT_EQ(p.kind, PlcProblemKind::Intersection);
}

// check_refined() (refined_check.h) tests exactly the pairs with a suspect simplex: with every
// simplex suspect it finds what check() finds; with the dented vertex's triangles suspect (each
// intersection has one) it finds them all; with none suspect it trusts the rest and finds nothing.
TEST(PlcCheck, RefinedCheckTestsThePairsWithASuspectSimplex) {
  Plc<3> box = grid_box_surface(8);
  uint32_t dented = kNone;
  for (uint32_t i = 0; i < box.num_points(); ++i)
    if (box.points[3 * i] == 4 && box.points[3 * i + 1] == 4 && box.points[3 * i + 2] == 8) dented = i;
  ASSERT_NE(dented, kNone);
  std::vector<char> none(box.num_simplices(), 0), all(box.num_simplices(), 1), at_dent(box.num_simplices(), 0);
  for (std::size_t j = 0; j < box.num_simplices(); ++j)
    for (int k = 0; k < 3; ++k) at_dent[j] |= box.simplices[3 * j + k] == dented;
  EXPECT_NO_THROW(detail::check_refined(box, all));  // still valid
  box.points[3 * dented + 2] = -1;  // its triangles pierce the bottom face
  uint64_t expected = 0;
  find_problems(box, 10, &expected);
  ASSERT_GT(expected, 0u);
  const auto found = [&](const std::vector<char>& suspect) -> uint64_t {
    try {
      detail::check_refined(box, suspect);
    } catch (const PlcError& e) {
      for (const auto& p : e.problems()) EXPECT_EQ(p.kind, PlcProblemKind::Intersection);
      return e.total();
    }
    return 0;
  };
  EXPECT_EQ(found(all), expected);
  EXPECT_EQ(found(at_dent), expected);
  EXPECT_EQ(found(none), 0u);
  EXPECT_THROW(detail::check_refined(box, std::vector<char>(3, 1)), std::invalid_argument);
}

TEST(PlcCheck, Segments2D) {
  Plc<2> square;
  square.points = {0, 0, 1, 0, 1, 1, 0, 1};
  square.simplices = {0, 1, 1, 2, 2, 3, 3, 0};
  EXPECT_TRUE(find_problems(square).empty());
  Plc<2> crossing = square;
  crossing.simplices.insert(crossing.simplices.end(), {0, 2, 1, 3});
  EXPECT_TRUE(has(crossing, PlcProblemKind::Intersection, {4, 5}));
  Plc<2> t_junction = square;
  t_junction.points.insert(t_junction.points.end(), {0.5, 0, 0.5, 0.5});
  t_junction.simplices.insert(t_junction.simplices.end(), {4, 5});  // 4 lies on segment 0-1
  EXPECT_TRUE(has(t_junction, PlcProblemKind::Intersection, {0, 4}));
  Plc<2> collinear = square;
  collinear.points.insert(collinear.points.end(), {0.5, 0});
  collinear.simplices.insert(collinear.simplices.end(), {0, 4});  // overlaps 0-1 from the shared end
  EXPECT_TRUE(has(collinear, PlcProblemKind::Intersection, {0, 4}));
}

TEST(PlcCheck, Tetrahedra4D) {
  Plc<4> plc;
  plc.points = {0, 0, 0, 0,  2, 0, 0, 0,  0, 2, 0, 0,  0, 0, 2, 0,
                0.5, 0.5, 0.5, -1,  0.5, 0.5, 0.5, 1,  5, 5, 5, 5,  6, 5, 7, 1};
  plc.simplices = {0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_TRUE(has(plc, PlcProblemKind::Intersection, {0, 1}));
  for (int i = 4; i < 8; ++i) plc.points[4 * i] += 10;
  EXPECT_TRUE(find_problems(plc).empty());
}

TEST(PlcCheck, ErrorMessageNamesElements) {
  Plc<3> plc = unit_cube_surface();
  plc.simplices[3 * 2] = 42;
  try {
    check(plc);
    FAIL() << "no error";
  } catch (const PlcError& e) {
    EXPECT_EQ(e.total(), 1u);
    EXPECT_NE(std::string(e.what()).find("simplex 2 names point 42"), std::string::npos) << e.what();
  }
}

}  // namespace
