// The cavity sweep (core/src/cavity/cavity_cdt.h): the Delaunay tetrahedralization, then the sweep
// only where constraints are missing. Its answer must be the sweep's, simplex for simplex, and it
// must be its own: CdtStatistics::algorithm stays CavitySweep only when the cavity path decided
// without sweeping the whole PLC, so every test here checks that too — a path that always fell back
// would pass the agreement tests of the other suites unnoticed.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "cad_noise.h"
#include "cavity/disturbed.h"
#include "simplex_interior.h"
#include "integer_sphere.h"
#include "random_plc.h"
#include "sweepcdt/cdt.h"
#include "test_shapes.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

struct Run {
  Triangulation<3> tri;
  CdtStatistics stats;
};

Run run(const Plc<3>& plc, Algorithm algorithm, Options options = {}) {
  Run r;
  options.algorithm = algorithm;
  options.statistics = &r.stats;
  r.tri = cdt(plc, options);
  return r;
}

// The cavity sweep equals the sweep sphere on `plc` and decided it itself; returns its statistics.
CdtStatistics expect_same_as_sweep(const Plc<3>& plc, const std::string& what, const Options& options = {}) {
  const Run sphere = run(plc, Algorithm::SweepSphere, options);
  const Run cavity = run(plc, Algorithm::CavitySweep, options);
  EXPECT_EQ(fixtures::simplex_set(cavity.tri), fixtures::simplex_set(sphere.tri)) << what;
  EXPECT_EQ(cavity.tri.points, sphere.tri.points) << what;
  EXPECT_EQ(cavity.stats.algorithm, Algorithm::CavitySweep) << what << ": the whole PLC was swept";
  return cavity.stats;
}

// Random constraints among grid points inside their convex hull (degenerate everywhere), the hull
// a far box: where the sweep finds a CDT, the cavity sweep finds the same one by itself; where it
// finds none, neither does the cavity sweep. (A cavity that reaches the convex hull is swept whole,
// cavity_plc.h: the far box keeps them inside.)
TEST(CavitySweep, RandomConstraintsInTheConvexHull) {
  int with_cdt = 0, with_cavities = 0, without_cdt = 0;
  for (uint64_t seed = 0; seed < 500; ++seed) {
    std::mt19937_64 rng(seed);
    Plc<3> plc = fixtures::random_constrained_plc<3>(rng, 5, 8, 1 + seed % 2);
    for (const double x : {-20.0, 24.0})
      for (const double y : {-21.0, 25.0})
        for (const double z : {-22.0, 26.0}) plc.points.insert(plc.points.end(), {x, y, z});
    const std::string what = "seed " + std::to_string(seed);
    bool sweep_found = true;
    try {
      run(plc, Algorithm::SweepSphere);
    } catch (const NoCdtError&) {
      sweep_found = false;
    }
    if (!sweep_found) {
      EXPECT_THROW(run(plc, Algorithm::CavitySweep), NoCdtError) << what;
      ++without_cdt;
      continue;
    }
    const CdtStatistics stats = expect_same_as_sweep(plc, what);
    ++with_cdt;
    with_cavities += stats.missing_constraints > 0;
  }
  EXPECT_GE(with_cavities, 10) << "few PLCs had a constraint missing from the Delaunay tetrahedralization";
  EXPECT_GE(without_cdt, 1) << "NoCdtError was never checked";
  std::printf("  %d PLCs with a CDT (%d with missing constraints), %d without\n", with_cdt, with_cavities, without_cdt);
}

// Two constraining triangles ABC and ACD in the plane z = 0 whose Delaunay diagonal is BD instead
// (the rhombus is short across BD), between apexes E above and F below: the Delaunay faces ABD and
// BCD overlap the constraints in their plane, and no Delaunay tetrahedron meets a constraint in its
// interior — only the overlap in a facet's plane marks the four tetrahedra as disturbed. (This PLC has
// no CDT, D being visible inside every sphere through ABC; both algorithms say so.)
TEST(CavitySweep, ConstraintsOverlappingDelaunayFacesInTheirPlaneDisturbThem) {
  Plc<3> plc;
  plc.points = {0, 0, 0, 2, 1, 0, 4, 0, 0, 2, -1, 0, 2, 0.2, 3, 1.9, -0.1, -3};
  plc.simplices = {0, 1, 2, 0, 2, 3};
  const detail::DelaunayMesh dt = detail::delaunay_mesh(plc.points);
  ASSERT_EQ(dt.tets.size(), 16u) << "the bipyramid over ABD and BCD";
  const detail::ConstraintFaces faces = detail::constraint_faces(plc, dt, 1);
  EXPECT_EQ(faces.missing, (std::vector<uint32_t>{0, 1}));
  for (std::size_t t = 0; t < 4; ++t)
    for (uint32_t c = 0; c < 2; ++c)
      EXPECT_FALSE((detail::interior_meets<3>({plc.point(dt.tets[4 * t]), plc.point(dt.tets[4 * t + 1]), plc.point(dt.tets[4 * t + 2]),
                                               plc.point(dt.tets[4 * t + 3])},
                                              {plc.point(plc.simplex(c)[0]), plc.point(plc.simplex(c)[1]), plc.point(plc.simplex(c)[2])})));
  EXPECT_EQ(detail::disturbed_tetrahedra(plc, dt, faces.missing).tets, (std::vector<uint8_t>{1, 1, 1, 1}));
  EXPECT_THROW(run(plc, Algorithm::SweepSphere), NoCdtError);
  EXPECT_THROW(run(plc, Algorithm::CavitySweep), NoCdtError);
}

// Closed surfaces (notated, facet-bounded) refined with Steiner points: the refined PLC has a CDT,
// and its constraints are mostly but not all Delaunay faces. Compared with the deletion pass off, so
// that the two triangulations of the same refined PLC are compared.
TEST(CavitySweep, SurfacesWithSteinerPoints) {
  Options options = mesh_defaults();
  options.remove_steiner_points = false;
  Plc<3> nested;  // a box in a box: a cavity in the domain
  fixtures::add_box(nested, {0, 0, 0}, {4, 4, 4}, true);
  fixtures::add_box(nested, {1, 1, 1}, {2, 3, 2}, false);
  const std::pair<std::string, Plc<3>> cases[] = {
      {"needle", fixtures::needle(24, 0.3)},
      {"comb", fixtures::extruded_columns({0, 1, 1.2, 3, 3.1, 5}, {3, 0.5, 3, 0.2, 4}, 2)},
      {"comb with CAD noise", sweepcdt::testing::with_cad_noise(fixtures::extruded_columns({0, 1, 1.2, 3, 3.1, 5}, {3, 0.5, 3, 0.2, 4}, 2), 0.5, 7)},
      {"needle, triangles as facets", fixtures::needle(16, 0.2)},
      {"box in a box", nested},
  };
  uint64_t missing = 0;
  for (const auto& [what, plc] : cases) {
    Options o = options;
    if (what == "needle, triangles as facets") o.facets = FacetMode::Triangles;
    const CdtStatistics stats = expect_same_as_sweep(plc, what, o);
    missing += stats.missing_constraints;
    // And with the deletion pass: a valid CDT of what is left.
    Options with_deletion = o;
    with_deletion.algorithm = Algorithm::CavitySweep;
    Plc<3> triangulated;
    const Triangulation<3> tri = cdt(plc, with_deletion, &triangulated);
    EXPECT_TRUE(validate_triangulated(tri, triangulated).ok()) << what;
  }
  EXPECT_GT(missing, 0u) << "no surface exercised a cavity";
}

// Exactly cospherical: the hull of every integer point on x^2 + y^2 + z^2 = 4001 (864 points, every
// insphere test among them an exact zero) as a closed surface and as a point set.
TEST(CavitySweep, ExactlyCosphericalIntegerSphere) {
  const Plc<3> hull = fixtures::integer_sphere_hull(4001);
  ASSERT_EQ(hull.num_points(), 864u);  // r3(4001), counted by a separate brute-force loop
  ASSERT_EQ(hull.num_simplices(), 2 * 864u - 4);  // a closed triangulated sphere with every point on it
  expect_same_as_sweep(hull, "integer sphere, facets");
  Plc<3> points;
  points.points = hull.points;
  const CdtStatistics stats = expect_same_as_sweep(points, "integer sphere, points");
  EXPECT_EQ(stats.missing_constraints, 0u);
}

// Several bodies, one inside another's cavity, and a convex hull domain without constraints.
TEST(CavitySweep, BodiesAndPointSets) {
  Plc<3> bodies;
  fixtures::add_box(bodies, {0, 0, 0}, {6, 6, 6}, true);
  fixtures::add_box(bodies, {1, 1, 1}, {5, 5, 5}, false);
  fixtures::add_box(bodies, {2, 2.5, 2}, {3, 3.5, 4}, true);
  expect_same_as_sweep(bodies, "a body in another's cavity", mesh_defaults());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  Plc<3> points;
  for (int i = 0; i < 3 * 300; ++i) points.points.push_back(u(rng));
  const CdtStatistics stats = expect_same_as_sweep(points, "random points");
  EXPECT_EQ(stats.missing_constraints, 0u);
  EXPECT_EQ(stats.cavity_tetrahedra, 0u);
}

}  // namespace
