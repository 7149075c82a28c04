// Gift-wrapping (paper §2) against independent oracles: brute-force perturbed Delaunay (exact set
// equality, unconstrained, D = 2..5 on degenerate grids), validate() on facet-bounded domains, and
// NoCdtError on PLCs that have no CDT.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "brute_force_delaunay.h"
#include "sweepcdt/cdt.h"
#include "triangulation_util.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/validate.h"
#include "off_reader.h"
#include "test_shapes.h"

using namespace sweepcdt;

namespace {

template <int D>
void equals_brute_force(int count, int grid, int seeds) {
  int compared = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(7000 * D + seed);
    Plc<D> plc;
    plc.points = fixtures::distinct_grid_points<D>(rng, count, grid);
    const auto reference = fixtures::brute_force_delaunay<D>(plc.points);
    if (reference.num_simplices() == 0) {
      EXPECT_THROW(cdt(plc), PlcError);  // lower-dimensional
      continue;
    }
    ++compared;
    const auto tri = cdt(plc);
    EXPECT_EQ(fixtures::simplex_set(tri), fixtures::simplex_set(reference)) << "D=" << D << " seed " << seed;
    EXPECT_TRUE(validate(tri, plc).ok());
  }
  EXPECT_GE(compared, seeds / 2);
}

TEST(GiftWrap, EqualsBruteForceDelaunay2D) { equals_brute_force<2>(14, 3, 30); }
TEST(GiftWrap, EqualsBruteForceDelaunay3D) { equals_brute_force<3>(12, 2, 30); }
TEST(GiftWrap, EqualsBruteForceDelaunay4D) { equals_brute_force<4>(10, 2, 15); }
TEST(GiftWrap, EqualsBruteForceDelaunay5D) { equals_brute_force<5>(10, 1, 8); }

template <int D>
void expect_cdt(const Plc<D>& plc, std::size_t expected_regions = 1) {
  Triangulation<D> tri;
  try {
    tri = cdt(plc);
  } catch (const std::exception& e) {
    FAIL() << e.what();
  }
  const auto report = validate(tri, plc);
  EXPECT_TRUE(report.ok()) << report.summary();
  std::set<int32_t> regions(tri.regions.begin(), tri.regions.end());
  EXPECT_EQ(regions.size(), expected_regions);
}

TEST(GiftWrap, UnitCube) { expect_cdt(fixtures::unit_cube_surface()); }
// Paper §6: "The order in which the vertices are perturbed can determine whether or not a
// triangulation is discovered." grid_box_surface(1) is the unit cube numbered so that its only
// boundary-respecting tetrahedralization (the six tetrahedra around (0,0,0)-(1,1,1)) is not locally
// Delaunay under the vertex-id perturbation: that perturbed PLC has no CDT. cdt() then tries the
// next orders (perturbation_order.h) and finds it, with every algorithm.
TEST(GiftWrap, CosphericalCubeGetsItsCdtUnderAnotherOrder) {
  const Plc<3> plc = fixtures::grid_box_surface(1);
  Triangulation<3> kuhn;
  kuhn.points = plc.points;
  kuhn.num_input_points = 8;
  auto id = [&](int x, int y, int z) {
    for (uint32_t i = 0; i < 8; ++i)
      if (plc.point(i)[0] == x && plc.point(i)[1] == y && plc.point(i)[2] == z) return i;
    return kNone;
  };
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& order : axes) {
    int c[3] = {0, 0, 0};
    std::array<uint32_t, 4> t{id(0, 0, 0)};
    for (int k = 0; k < 3; ++k) c[order[k]] = 1, t[k + 1] = id(c[0], c[1], c[2]);
    if (predicates::orient<3>({kuhn.point(t[0]), kuhn.point(t[1]), kuhn.point(t[2]), kuhn.point(t[3])}) ==
        predicates::Sign::Negative)
      std::swap(t[0], t[1]);
    kuhn.simplices.insert(kuhn.simplices.end(), t.begin(), t.end());
  }
  compute_neighbors(kuhn);
  const auto report = validate(kuhn, plc);
  EXPECT_TRUE(validate(kuhn, plc, ValidationLevel::Topology).ok());
  EXPECT_EQ(report.count("locally-delaunay"), 1u) << report.summary();

  for (Algorithm algorithm : {Algorithm::GiftWrap, Algorithm::SweepSphere, Algorithm::SweepPlane}) {
    Options options;  // SteinerMode::None: the PLC exactly as given
    options.algorithm = algorithm;
    CdtStatistics stats;
    options.statistics = &stats;
    Triangulation<3> tri;
    try {
      tri = cdt(plc, options);
    } catch (const std::exception& e) {
      ADD_FAILURE() << to_string(algorithm) << ": " << e.what();
      continue;
    }
    EXPECT_TRUE(validate(tri, plc).ok()) << to_string(algorithm) << "\n" << validate(tri, plc).summary();
    EXPECT_EQ(tri.num_input_points, 8u);
    EXPECT_EQ(tri.num_points(), 8u) << "no Steiner points";
    EXPECT_TRUE(tri.steiner_on.empty());
    EXPECT_GT(stats.perturbation_orders, 1u) << to_string(algorithm);
    EXPECT_FALSE(tri.perturbation_rank.empty());
    EXPECT_EQ(fixtures::simplex_set(tri), fixtures::simplex_set(kuhn)) << to_string(algorithm);
    tri.perturbation_rank.clear();  // the same simplices, perturbed by vertex id
    EXPECT_EQ(validate(tri, plc).count("locally-delaunay"), 1u) << to_string(algorithm);
  }
}

TEST(GiftWrap, CubeWithCubicCavity) {
  Plc<3> plc;
  fixtures::add_box(plc, {0, 0, 0}, {4, 4, 4}, true);
  fixtures::add_box(plc, {1, 1, 1}, {2, 3, 2}, false);
  expect_cdt(plc);
  // The cavity is not meshed: total volume 64 - 2.
  const auto tri = cdt(plc);
  double volume = 0;
  for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
    predicates::Coords<4> c;
    for (int i = 0; i < 4; ++i) c[i] = tri.point(tri.simplex(t)[i]);
    volume += predicates::orient_value<3>(c) / 6;
  }
  EXPECT_DOUBLE_EQ(volume, 62.0);
}

TEST(GiftWrap, TwoDisjointCubesAreTwoRegions) {
  Plc<3> plc;
  fixtures::add_box(plc, {0, 0, 0}, {1, 1, 1}, true);
  fixtures::add_box(plc, {3, 0, 0}, {4, 2, 1}, true);
  expect_cdt(plc, 2);
}

TEST(GiftWrap, RegionSeedsNameRegions) {
  Plc<3> plc;
  fixtures::add_box(plc, {0, 0, 0}, {1, 1, 1}, true);
  fixtures::add_box(plc, {3, 0, 0}, {4, 2, 1}, true);
  plc.region_seeds = {{{3.5, 1, 0.5}, 7}};
  const auto tri = cdt(plc);
  for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
    const bool second = tri.point(tri.simplex(t)[0])[0] >= 3;
    EXPECT_EQ(tri.regions[t], second ? 7 : 8);
  }
}

TEST(GiftWrap, InternalWallWithDomainOnBothSides) {
  // Two tetrahedra glued along the unnotated triangle (0 1 2): a domain on both sides of it.
  Plc<3> plc;
  plc.points = {0, 0, 0, 3, 0, 0, 0, 3, 0, 1, 1, 2, 1, 1, -2};
  plc.simplices = {0, 1, 2,  0, 1, 3, 1, 2, 3, 2, 0, 3,  0, 1, 4, 1, 2, 4, 2, 0, 4};
  plc.exterior = {ExteriorSide::None};
  // Notate each outer face so that the centroid of its own tetrahedron is on the domain side.
  for (std::size_t j = 1; j < 7; ++j) {
    const uint32_t* f = plc.simplex(j);
    const double centroid[3] = {1, 1, f[2] == 3 ? 0.5 : -0.5};  // of tetrahedron 0123 or 0124
    const auto side = predicates::orient<3>({plc.point(f[0]), plc.point(f[1]), plc.point(f[2]), centroid});
    plc.exterior.push_back(side == predicates::Sign::Positive ? ExteriorSide::Negative : ExteriorSide::Positive);
  }
  ASSERT_TRUE(find_problems(plc).empty());
  expect_cdt(plc, 2);
  EXPECT_EQ(cdt(plc).num_simplices(), 2u);
}

// Non-manifold domains: two tetrahedra meeting at one vertex, and two meeting along one edge.
TEST(GiftWrap, NonManifoldDomains) {
  Plc<3> vertex;
  vertex.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1};
  fixtures::add_tetrahedron(vertex, {0, 1, 2, 3});
  fixtures::add_tetrahedron(vertex, {0, 4, 5, 6});
  ASSERT_TRUE(find_problems(vertex).empty());
  expect_cdt(vertex, 2);
  EXPECT_EQ(cdt(vertex).num_simplices(), 2u);

  Plc<3> edge;
  edge.points = {0, 0, 0, 0, 0, 1, 1, 0, 0.25, 1, 1, 0.75, -1, 0, 0.5, -1, -1, 0.25};
  fixtures::add_tetrahedron(edge, {0, 1, 2, 3});
  fixtures::add_tetrahedron(edge, {0, 1, 4, 5});
  ASSERT_TRUE(find_problems(edge).empty());
  expect_cdt(edge, 2);
  EXPECT_EQ(cdt(edge).num_simplices(), 2u);
}

TEST(GiftWrap, PolygonWithHole2D) {
  Plc<2> plc;
  plc.points = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 1, 3, 3, 3, 3, 1, 2, 0.5};
  // Outer square counterclockwise (inside = positive = left side), hole clockwise.
  plc.simplices = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  plc.exterior.assign(8, ExteriorSide::Negative);
  expect_cdt(plc);
}

TEST(GiftWrap, SchonhardtPrismHasNoCdt) {
  for (double twist : {0.0, 0.2, 0.5, 1e-9}) {
    const Plc<3> prism = fixtures::twisted_prism(twist);
    ASSERT_TRUE(find_problems(prism).empty()) << "twist " << twist;
    try {
      cdt(prism);
      ADD_FAILURE() << "twist " << twist << ": a CDT was returned";
    } catch (const NoCdtError& e) {
      EXPECT_FALSE(std::string(e.what()).empty());
    }
  }
}

TEST(GiftWrap, OpenSurfaceIsNotADomain) {
  Plc<3> plc = fixtures::unit_cube_surface();
  plc.simplices.resize(plc.simplices.size() - 6);  // two triangles of one face removed
  plc.exterior.resize(plc.num_simplices());
  EXPECT_THROW(cdt(plc), NoCdtError);
}

}  // namespace

namespace {

// Shared sample meshes (../shared/data). Missing files are reported as skipped, never passed.
TEST(GiftWrapSharedData, Icosahedron) {
  const auto plc = fixtures::read_off_surface(std::string(SWEEPCDT_SHARED_DATA) + "/off/icosahedron.off");
  if (!plc) GTEST_SKIP() << "shared data not found at " << SWEEPCDT_SHARED_DATA;
  ASSERT_TRUE(find_problems(*plc).empty());
  expect_cdt(*plc);
}

// With constraints, D = 3..5: Shewchuk's companion theorem says a CDT exists when every ridge of
// every constraining simplex is strongly Delaunay. So the constraints are built from ridges of the
// Delaunay triangulation of random points (strongly Delaunay in general position) while not being
// Delaunay facets themselves: a CDT must exist, differ from the Delaunay triangulation, and pass
// validate().
template <int D>
void strongly_delaunay_constraints(int points, int constraints, int seeds) {
  int changed = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(9000 * D + seed);
    std::uniform_real_distribution<double> u(0, 1);
    Plc<D> plc;
    for (int i = 0; i < D * points; ++i) plc.points.push_back(u(rng));
    const auto delaunay = cdt(plc);
    std::set<std::vector<uint32_t>> ridges, facets;
    for (std::size_t t = 0; t < delaunay.num_simplices(); ++t) {
      std::vector<uint32_t> s(delaunay.simplex(t), delaunay.simplex(t) + D + 1);
      std::sort(s.begin(), s.end());
      for (int i = 0; i <= D; ++i) {
        std::vector<uint32_t> f = s;
        f.erase(f.begin() + i);
        facets.insert(f);
        for (int j = 0; j < D; ++j) {
          std::vector<uint32_t> r = f;
          r.erase(r.begin() + j);
          ridges.insert(r);
        }
      }
    }
    std::vector<std::vector<uint32_t>> ridge_list(ridges.begin(), ridges.end());
    std::uniform_int_distribution<std::size_t> pick_ridge(0, ridge_list.size() - 1);
    for (int tries = 0; tries < 2000 && static_cast<int>(plc.num_simplices()) < constraints; ++tries) {
      std::vector<uint32_t> c = ridge_list[pick_ridge(rng)];
      c.push_back(static_cast<uint32_t>(rng() % points));
      std::sort(c.begin(), c.end());
      if (std::adjacent_find(c.begin(), c.end()) != c.end() || facets.count(c)) continue;
      bool strongly_delaunay = true;
      for (int j = 0; j < D && strongly_delaunay; ++j) {
        std::vector<uint32_t> r = c;
        r.erase(r.begin() + j);
        strongly_delaunay = ridges.count(r) > 0;
      }
      if (!strongly_delaunay) continue;
      plc.simplices.insert(plc.simplices.end(), c.begin(), c.end());
      if (!find_problems(plc).empty()) plc.simplices.resize(plc.simplices.size() - D);
    }
    if (plc.num_simplices() == 0) continue;
    Triangulation<D> tri;
    try {
      tri = cdt(plc);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "D=" << D << " seed " << seed << ": " << e.what();
      continue;
    }
    const auto report = validate(tri, plc);
    EXPECT_TRUE(report.ok()) << "D=" << D << " seed " << seed << "\n" << report.summary();
    changed += fixtures::simplex_set(tri) != fixtures::simplex_set(delaunay);
  }
  EXPECT_GE(changed, seeds / 2) << "the constraints rarely mattered: this test checks little";
}

TEST(GiftWrap, StronglyDelaunayConstraints3D) { strongly_delaunay_constraints<3>(40, 8, 20); }
TEST(GiftWrap, StronglyDelaunayConstraints4D) { strongly_delaunay_constraints<4>(24, 5, 6); }
TEST(GiftWrap, StronglyDelaunayConstraints5D) { strongly_delaunay_constraints<5>(28, 3, 3); }

}  // namespace
