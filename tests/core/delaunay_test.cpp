// delaunay_simplices<3> (incremental Bowyer–Watson, core/src/delaunay/delaunay.h) against the sweep
// sphere's unconstrained Delaunay triangulation: identical tetrahedron sets under the §6 perturbation
// on random points and on inputs full of cospherical and coplanar points (grids, spheres, points in
// the planes of hull triangles, inside and outside their circumcircles), in several insertion orders.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <set>

#include "delaunay/delaunay.h"
#include "sweep/sweep_cdt.h"
#include "gift_wrap.h"
#include "sweepcdt/error.h"
#include "sweepcdt/predicates/orientation.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

using Tet = std::array<uint32_t, 4>;
using TetSet = std::set<std::vector<uint32_t>>;

TetSet sweep_delaunay(const std::vector<double>& points) {
  Plc<3> plc;
  plc.points = points;
  Options options;
  CdtStatistics stats;
  return fixtures::simplex_set(detail::sweep_cdt<3>(plc, detail::seed_simplex(plc), options, stats));
}

TetSet as_set(const std::vector<Tet>& tets) {
  TetSet set;
  for (Tet t : tets) {
    std::sort(t.begin(), t.end());
    set.insert(std::vector<uint32_t>(t.begin(), t.end()));
  }
  return set;
}

// Positive orientation, no repeated tetrahedron, every triangle in one or two tetrahedra, and the
// hull triangles (in one) form a closed surface: each of their edges is in exactly two of them.
void expect_valid(const std::vector<double>& points, const std::vector<Tet>& tets, const std::string& what) {
  std::map<std::array<uint32_t, 3>, int> triangles;
  for (const Tet& t : tets) {
    const double* x[4];
    for (int k = 0; k < 4; ++k) x[k] = points.data() + 3 * t[k];
    ASSERT_EQ(predicates::orient<3>({x[0], x[1], x[2], x[3]}), predicates::Sign::Positive) << what;
    for (int i = 0; i < 4; ++i) {
      std::array<uint32_t, 3> f;
      for (int k = 0, r = 0; k < 4; ++k)
        if (k != i) f[r++] = t[k];
      std::sort(f.begin(), f.end());
      ++triangles[f];
    }
  }
  EXPECT_EQ(as_set(tets).size(), tets.size()) << what << ": repeated tetrahedron";
  std::map<std::pair<uint32_t, uint32_t>, int> hull_edges;
  for (const auto& [f, count] : triangles) {
    ASSERT_LE(count, 2) << what << ": triangle in more than two tetrahedra";
    if (count == 1)
      for (int i = 0; i < 3; ++i) ++hull_edges[std::minmax(f[i], f[(i + 1) % 3])];
  }
  for (const auto& [e, count] : hull_edges) ASSERT_EQ(count, 2) << what << ": hull is not closed";
}

// The default (BRIO) order plus index order, reverse order and random orders all give the sweep's
// triangulation.
void expect_same_as_sweep(const std::vector<double>& points, const std::string& what, int random_orders = 2) {
  const TetSet reference = sweep_delaunay(points);
  const std::vector<Tet> tets = detail::delaunay_simplices<3>(points);
  expect_valid(points, tets, what);
  EXPECT_EQ(as_set(tets), reference) << what;

  const auto orders = fixtures::insertion_orders(static_cast<uint32_t>(points.size() / 3), random_orders);
  for (std::size_t k = 0; k < orders.size(); ++k) {
    const std::vector<Tet> again = detail::delaunay_simplices_in_order<3>(points, orders[k]);
    expect_valid(points, again, what + " order " + std::to_string(k));
    EXPECT_EQ(as_set(again), reference) << what << " order " << std::to_string(k);
  }
}

std::vector<double> random_points(int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<double> points(3 * count);
  for (double& x : points) x = coordinate(rng);
  return points;
}

std::vector<double> grid(int nx, int ny, int nz) {
  std::vector<double> points;
  for (int x = 0; x < nx; ++x)
    for (int y = 0; y < ny; ++y)
      for (int z = 0; z < nz; ++z) points.insert(points.end(), {double(x), double(y), double(z)});
  return points;
}

TEST(Delaunay3, RandomPoints) {
  for (int count : {4, 5, 10, 50, 200, 1000})
    for (uint64_t seed = 0; seed < 4; ++seed)
      expect_same_as_sweep(random_points(count, seed), "random " + std::to_string(count) + " seed " + std::to_string(seed));
  expect_same_as_sweep(random_points(5000, 7), "random 5000", 1);
}

TEST(Delaunay3, FullGrids) {
  expect_same_as_sweep(grid(2, 2, 2), "2x2x2 grid", 6);
  expect_same_as_sweep(grid(3, 3, 3), "3x3x3 grid", 6);
  expect_same_as_sweep(grid(6, 6, 6), "6x6x6 grid");
  expect_same_as_sweep(grid(10, 4, 2), "10x4x2 grid");
  expect_same_as_sweep(grid(12, 12, 2), "12x12x2 grid");
}

// Whether all points lie in one plane (exactly): then there is no tetrahedron.
bool all_coplanar(const std::vector<double>& points) {
  const std::size_t n = points.size() / 3;
  const auto p = [&](std::size_t i) { return points.data() + 3 * i; };
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k)
        if (predicates::orient<3>({p(0), p(i), p(j), p(k)}) != predicates::Sign::Zero) return false;
  return true;
}

TEST(Delaunay3, RandomGridSubsets) {
  int compared = 0;
  for (uint64_t seed = 0; seed < 60; ++seed) {
    std::mt19937_64 rng(seed);
    const int size = seed % 3 == 0 ? 2 : 3;
    const int count = std::min(8 + static_cast<int>(seed % 30), (size + 1) * (size + 1) * (size + 1));
    const std::vector<double> points = fixtures::distinct_grid_points<3>(rng, count, size);
    if (all_coplanar(points)) {
      EXPECT_THROW(detail::delaunay_simplices<3>(points), Error) << "seed " << seed;
      continue;
    }
    expect_same_as_sweep(points, "grid subset seed " + std::to_string(seed));
    ++compared;
  }
  EXPECT_GE(compared, 50);
}

// All integer points on spheres: every tetrahedron is cospherical with all the others' vertices.
TEST(Delaunay3, CosphericalPoints) {
  for (int r2 : {3, 9, 11, 26, 50, 75}) {
    std::vector<double> points;
    for (int x = -9; x <= 9; ++x)
      for (int y = -9; y <= 9; ++y)
        for (int z = -9; z <= 9; ++z)
          if (x * x + y * y + z * z == r2) points.insert(points.end(), {double(x), double(y), double(z)});
    expect_same_as_sweep(points, "sphere r^2=" + std::to_string(r2), 4);
    points.insert(points.end(), {0.0, 0.0, 0.0});  // and its centre
    expect_same_as_sweep(points, "sphere with centre r^2=" + std::to_string(r2), 4);
  }
}

// Almost all points in one plane (a hull facet with many points, triangulated by the 2D perturbed
// Delaunay rule), plus a few points off it.
TEST(Delaunay3, MostlyCoplanar) {
  for (uint64_t seed = 0; seed < 8; ++seed) {
    std::mt19937_64 rng(100 + seed);
    std::vector<double> points;
    std::uniform_int_distribution<int> c(0, 6);
    std::set<std::array<int, 2>> seen;
    while (seen.size() < 30) {
      const std::array<int, 2> p{c(rng), c(rng)};
      if (seen.insert(p).second) points.insert(points.end(), {double(p[0]), double(p[1]), 0.0});
    }
    const int off = 1 + static_cast<int>(seed % 3);
    for (int k = 0; k < off; ++k) points.insert(points.end(), {double(c(rng)), double(c(rng)), k % 2 ? -3.0 : 2.0 + k});
    // Put the off-plane points first or last in index order: the perturbation order changes.
    if (seed % 2) {
      std::vector<double> rotated(points.end() - 3 * off, points.end());
      rotated.insert(rotated.end(), points.begin(), points.end() - 3 * off);
      points = rotated;
    }
    expect_same_as_sweep(points, "mostly coplanar seed " + std::to_string(seed), 4);
  }
}

// Integer points on a few planes (two parallel, two slanted), so that hull facets and interior
// triangles carry many coplanar and cocircular points.
TEST(Delaunay3, PointsOnFewPlanes) {
  for (uint64_t seed = 0; seed < 12; ++seed) {
    std::mt19937_64 rng(500 + seed);
    std::uniform_int_distribution<int> c(0, 6), plane(0, 3);
    std::set<std::array<int, 3>> seen;
    std::vector<double> points;
    while (seen.size() < 20 + 5 * seed) {
      const int a = c(rng), b = c(rng);
      std::array<int, 3> p;
      switch (plane(rng)) {
        case 0: p = {a, b, 0}; break;
        case 1: p = {a, b, 4}; break;
        case 2: p = {a, 6 - a, b}; break;
        default: p = {a, b, a}; break;
      }
      if (seen.insert(p).second) points.insert(points.end(), {double(p[0]), double(p[1]), double(p[2])});
    }
    expect_same_as_sweep(points, "few planes seed " + std::to_string(seed), 3);
  }
}

// A tetrahedron inserted first, then points in the planes of its faces: inside a face triangle, outside
// the triangle but inside its circumcircle, on the circumcircle, outside it, on an edge's line.
TEST(Delaunay3, PointsInHullFacePlanes) {
  const std::vector<double> corners{0, 0, 0, 12, 0, 0, 0, 12, 0, 0, 0, 12};
  const std::vector<std::array<double, 3>> extra{
      {5, 5, 0},   {10, 10, 0}, {12, 12, 0}, {14, -2, 0}, {-2, 14, 0}, {6, -1, 0},  {18, 0, 0},  {-4, 0, 0},
      {0, 5, 5},   {0, 10, 10}, {0, 12, 12}, {0, 14, -2}, {3, 0, 4},   {12, 0, 12}, {0, -3, 0},  {4, 4, 4},
      {6, 6, 0},   {0, 6, 6},   {6, 0, 6},   {-6, 18, 0}, {3, 3, 6},   {0, 0, -5},  {20, 20, 0}, {6, 6, -6}};
  for (uint64_t seed = 0; seed < 40; ++seed) {
    std::mt19937_64 rng(seed);
    std::vector<std::array<double, 3>> chosen = extra;
    std::shuffle(chosen.begin(), chosen.end(), rng);
    chosen.resize(4 + seed % 12);
    std::vector<double> points = corners;
    for (const auto& p : chosen) points.insert(points.end(), p.begin(), p.end());
    const uint32_t n = static_cast<uint32_t>(points.size() / 3);
    // The corners first (so the extra points meet the hull faces' planes), the rest shuffled.
    std::vector<uint32_t> order(n);
    for (uint32_t i = 0; i < n; ++i) order[i] = i;
    std::shuffle(order.begin() + 4, order.end(), rng);
    const TetSet reference = sweep_delaunay(points);
    const std::vector<Tet> tets = detail::delaunay_simplices_in_order<3>(points, order);
    expect_valid(points, tets, "face planes seed " + std::to_string(seed));
    EXPECT_EQ(as_set(tets), reference) << "face planes seed " << seed;
    // The same points with the ids reversed: the perturbation favours the other end.
    std::vector<double> reversed;
    for (uint32_t i = n; i-- > 0;) reversed.insert(reversed.end(), points.begin() + 3 * i, points.begin() + 3 * i + 3);
    expect_same_as_sweep(reversed, "face planes reversed ids seed " + std::to_string(seed), 2);
  }
}

// The spatial sort must survive an extent that overflows (it only orders; predicates are exact).
TEST(Delaunay3, HugeCoordinates) {
  std::vector<double> points = random_points(40, 99);
  for (double& x : points) x *= 1e308;
  const std::vector<Tet> tets = detail::delaunay_simplices<3>(points);
  expect_valid(points, tets, "huge");
  EXPECT_EQ(as_set(tets), sweep_delaunay(points));
}

TEST(Delaunay3, Throws) {
  EXPECT_THROW(detail::delaunay_simplices<3>({}), Error);
  EXPECT_THROW(detail::delaunay_simplices<3>({0, 0, 0, 1, 0, 0, 0, 1, 0}), Error);
  EXPECT_THROW(detail::delaunay_simplices<3>({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 5, 7, 0}), Error);  // flat
  EXPECT_THROW(detail::delaunay_simplices<3>({0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}), Error);           // collinear
  EXPECT_THROW(detail::delaunay_simplices<3>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0}), Error);  // duplicate
  EXPECT_THROW(detail::delaunay_simplices<3>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, 0.2, 0.2, 0.2, 0.2}), Error);
  EXPECT_THROW(detail::delaunay_simplices<3>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}), Error);  // not n x 3
  EXPECT_THROW(detail::delaunay_simplices_in_order<3>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 1, 2, 2}), Error);
  EXPECT_EQ(detail::delaunay_simplices<3>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}).size(), 1u);
}

// DelaunayEdges (kept between Steiner rounds): after each batch of appended points, has_edge agrees
// with the edges of the triangulation built from scratch, for every pair of points, and
// link_vertices with each point's edges; and a pair that
// may_have_changed calls unchanged really is (an edge exactly when it was one before the batch), and
// a pair it may call changed has an end among changed_points (each listed once): refinement looks
// only there. Random and grid points (ties decided by the perturbation).
std::set<std::pair<uint32_t, uint32_t>> edges_of(const std::vector<double>& points) {
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (const Tet& t : detail::delaunay_simplices<3>(points))
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert(std::minmax(t[i], t[j]));
  return edges;
}

// link_vertices(a): exactly the other ends of a's edges.
bool link_is_edges(detail::DelaunayEdges& edges, uint32_t a, const std::set<std::pair<uint32_t, uint32_t>>& expected) {
  std::vector<uint32_t> link;
  edges.link_vertices(a, link);
  std::set<uint32_t> got(link.begin(), link.end()), around;
  for (const auto& [x, y] : expected)
    if (x == a || y == a) around.insert(x == a ? y : x);
  return got == around;
}

void expect_incremental_edges(const std::vector<double>& all, const std::string& what) {
  const std::size_t n = all.size() / 3;
  std::vector<double> points(all.begin(), all.begin() + 3 * (n / 4));
  detail::DelaunayEdges incremental(points);
  std::set<std::pair<uint32_t, uint32_t>> before = edges_of(points);
  int unchanged = 0, partial = 0;
  std::size_t before_end = n / 4;
  for (const std::size_t end : {n / 2, n / 2 + 1, 3 * n / 4, n}) {
    points.insert(points.end(), all.begin() + points.size(), all.begin() + 3 * end);
    incremental.insert_new_points();
    const auto after = edges_of(points);
    const std::vector<uint32_t>& listed = incremental.changed_points();
    const std::set<uint32_t> changed(listed.begin(), listed.end());
    ASSERT_EQ(changed.size(), listed.size()) << what << ": a point listed twice";
    for (auto v = static_cast<uint32_t>(before_end); v < end; ++v)
      ASSERT_TRUE(changed.count(v)) << what << ": new point " << v << " not listed";
    if (changed.size() < end) ++partial;
    for (uint32_t a = 0; a < end; ++a) ASSERT_TRUE(link_is_edges(incremental, a, after)) << what << ": link of " << a << " with " << end << " points";
    for (uint32_t a = 0; a < end; ++a)
      for (uint32_t b = a + 1; b < end; ++b) {
        const bool edge = after.count({a, b}) > 0;
        ASSERT_EQ(incremental.has_edge(a, b), edge) << what << ": " << a << " " << b << " with " << end << " points";
        ASSERT_EQ(incremental.has_edge(b, a), edge) << what;
        if (incremental.may_have_changed(a, b))
          ASSERT_TRUE(changed.count(a) || changed.count(b)) << what << ": " << a << " " << b << " may have changed, neither end listed";
        else {
          ++unchanged;
          ASSERT_EQ(before.count({a, b}) > 0, edge) << what << ": " << a << " " << b << " changed unnoticed";
        }
      }
    before = after;
    before_end = end;
  }
  EXPECT_GT(unchanged, 0) << what << ": may_have_changed never said no, so it was not tested";
  EXPECT_GT(partial, 0) << what << ": every point always listed, so changed_points was not tested";
}

TEST(Delaunay3, EdgesKeptUpToDateAsPointsAreAdded) {
  for (uint64_t seed = 0; seed < 4; ++seed) expect_incremental_edges(random_points(160, seed), "random " + std::to_string(seed));
  for (uint64_t seed = 0; seed < 4; ++seed) {
    std::mt19937_64 rng(500 + seed);
    expect_incremental_edges(fixtures::distinct_grid_points<3>(rng, 120, 4), "grid " + std::to_string(seed));
  }
}

// rebind: a triangulation handed on to another copy of its points (lazy refinement's next attempt,
// steiner/refine.cpp) reads them there, the old vector gone, and goes on inserting the points
// appended to the new one: the same edges as a triangulation built from scratch.
TEST(Delaunay3, EdgesReboundToACopyOfThePoints) {
  const std::vector<double> all = random_points(120, 77);
  auto first = std::make_unique<std::vector<double>>(all.begin(), all.begin() + 3 * 80);
  detail::DelaunayEdges edges(*first);
  std::vector<double> copy = *first;
  first.reset();
  edges.rebind(copy);
  copy.insert(copy.end(), all.begin() + 3 * 80, all.end());
  edges.insert_new_points();
  const auto expected = edges_of(copy);
  for (uint32_t a = 0; a < 120; ++a)
    for (uint32_t b = a + 1; b < 120; ++b) ASSERT_EQ(edges.has_edge(a, b), expected.count({a, b}) > 0) << a << " " << b;
}

// Three sets of random points and three of distinct grid points (ties, coplanar hull facets), named.
std::vector<std::pair<std::string, std::vector<double>>> random_and_grid_cases(int random_count, uint64_t random_seed, int grid_count,
                                                                               int grid_size, uint64_t grid_seed) {
  std::vector<std::pair<std::string, std::vector<double>>> cases;
  for (uint64_t seed = 0; seed < 3; ++seed) cases.emplace_back("random " + std::to_string(seed), random_points(random_count, random_seed + seed));
  for (uint64_t seed = 0; seed < 3; ++seed) {
    std::mt19937_64 rng(grid_seed + seed);
    cases.emplace_back("grid " + std::to_string(seed), fixtures::distinct_grid_points<3>(rng, grid_count, grid_size));
  }
  return cases;
}

// A mesh's tetrahedra as a set (as_set), to compare with the triangulation built from scratch.
TetSet tets_of(const detail::DelaunayMesh& mesh) {
  std::vector<Tet> tets;
  for (std::size_t t = 0; t < mesh.tets.size(); t += 4) tets.push_back({mesh.tets[t], mesh.tets[t + 1], mesh.tets[t + 2], mesh.tets[t + 3]});
  return as_set(tets);
}

// A triangulation taken from a mesh (a refinement made again takes its last attempt's, refine.cpp)
// behaves as the one that made the mesh: has_edge and link_vertices as the triangulation from
// scratch, and so after more points are inserted into it, grid points included (ties, hull facets
// in one plane). Every point counts as changed after adopting, as after building; a mesh that
// misses a point is refused.
TEST(Delaunay3, EdgesFromAMeshGoOnAsTheTriangulationItCameFrom) {
  for (const auto& [what, all] : random_and_grid_cases(150, 40, 120, 4, 900)) {
    const std::size_t n = all.size() / 3;
    std::vector<double> points(all.begin(), all.begin() + 3 * (n / 2));
    const detail::DelaunayEdges built(points);
    const std::unique_ptr<detail::DelaunayEdges> taken = detail::DelaunayEdges::from_mesh(points, built.mesh());
    ASSERT_NE(taken, nullptr) << what;
    detail::DelaunayEdges& adopted = *taken;
    EXPECT_EQ(adopted.changed_points().size(), n / 2) << what;
    // A mesh of fewer points than given is none of theirs.
    const std::vector<double> more(all.begin(), all.begin() + 3 * (n / 2 + 1));
    EXPECT_EQ(detail::DelaunayEdges::from_mesh(more, built.mesh()), nullptr) << what;
    const std::vector<double> fewer(all.begin(), all.begin() + 3 * (n / 2 - 1));
    EXPECT_EQ(detail::DelaunayEdges::from_mesh(fewer, built.mesh()), nullptr) << what;
    for (const std::size_t end : {n / 2, n}) {
      points.insert(points.end(), all.begin() + points.size(), all.begin() + 3 * end);
      adopted.insert_new_points();
      const auto expected = edges_of(points);
      for (uint32_t a = 0; a < end; ++a) {
        ASSERT_TRUE(link_is_edges(adopted, a, expected)) << what << ": link of " << a << " with " << end << " points";
        for (uint32_t b = a + 1; b < end; ++b) ASSERT_EQ(adopted.has_edge(a, b), expected.count({a, b}) > 0) << what << ": " << a << " " << b;
      }
      EXPECT_EQ(tets_of(adopted.mesh()), as_set(detail::delaunay_simplices<3>(points))) << what << " with " << end << " points";
    }
  }
}

// insert_new_points(near): each point's location starts at the point `near` names (refinement names
// an end of the piece it splits), which changes the walk only: the same tetrahedra as from scratch,
// whatever is named — an inserted point beside it, one far off, a point on the hull (its simplex may
// be a ghost), one of the batch not inserted yet, the point itself, kNone. Random and grid points.
TEST(Delaunay3, PointsLocatedFromANamedPointGiveTheSameTriangulation) {
  for (const auto& [what, all] : random_and_grid_cases(200, 60, 160, 5, 700)) {
    const uint32_t n = static_cast<uint32_t>(all.size() / 3);
    for (int rule = 0; rule < 6; ++rule) {
      std::vector<double> points(all.begin(), all.begin() + 3 * (n / 4));
      detail::DelaunayEdges edges(points);
      std::mt19937_64 rng(rule);
      for (const uint32_t end : {n / 2, n / 2 + 3, n}) {
        const uint32_t first = static_cast<uint32_t>(points.size() / 3);
        points.insert(points.end(), all.begin() + points.size(), all.begin() + 3 * std::size_t{end});
        const auto near = [&](uint32_t id) -> uint32_t {
          switch (rule) {
            case 0: {  // the inserted point nearest to it
              uint32_t best = 0;
              double least = 1e300;
              for (uint32_t v = 0; v < first; ++v) {
                double d = 0;
                for (int k = 0; k < 3; ++k) d += (points[3 * v + k] - points[3 * id + k]) * (points[3 * v + k] - points[3 * id + k]);
                if (d < least) least = d, best = v;
              }
              return best;
            }
            case 1: return static_cast<uint32_t>(rng() % first);  // anywhere
            case 2: return 0;                                      // always the same one (on the hull, or not)
            case 3: return end - 1;                                // of the batch: not inserted until last
            case 4: return id;                                     // itself
            default: return kNone;
          }
        };
        edges.insert_new_points(near);
        ASSERT_EQ(tets_of(edges.mesh()), as_set(detail::delaunay_simplices<3>(points))) << what << ", rule " << rule << ", " << end << " points";
      }
    }
  }
}

// Not a timing assertion: prints both times for the report (bench/sweep_bench cube-points 33000).
TEST(Delaunay3, Large33kAgainstSweep) {
  const std::vector<double> points = random_points(33000, 2024);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Tet> tets = detail::delaunay_simplices<3>(points);
  const auto t1 = std::chrono::steady_clock::now();
  const TetSet reference = sweep_delaunay(points);
  const auto t2 = std::chrono::steady_clock::now();
  const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
  std::printf("33000 random points: delaunay_tetrahedra %.1f ms (%zu tets), sweep %.1f ms\n", ms(t1 - t0), tets.size(),
              ms(t2 - t1));
  EXPECT_EQ(as_set(tets), reference);
}

}  // namespace
