// The cavity sweep (core/src/cavity/cavity_cdt.h): the Delaunay tetrahedralization, then the sweep
// only where constraints are missing. Its answer must be the sweep's, simplex for simplex, and it
// must be its own: CdtStatistics::algorithm stays CavitySweep only when the cavity path decided
// without sweeping the whole PLC, so every test here checks that too — a path that always fell back
// would pass the agreement tests of the other suites unnoticed.
#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <random>
#include <set>
#include <string>

#include "cad_noise.h"
#include "cavity/cavity_cdt.h"
#include "cavity/disturbed.h"
#include "delaunay/delaunay.h"
#include "facets.h"
#include "gift_wrap.h"
#include "sweep/sweep_cdt.h"
#include "sweepcdt/validate.h"
#include "simplex_interior.h"
#include "simplex_intersection.h"
#include "integer_sphere.h"
#include "random_plc.h"
#include "sweepcdt/cdt.h"
#include "test_shapes.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

template <int D = 3>
struct Run {
  Triangulation<D> tri;
  CdtStatistics stats;
};

template <int D>
Run<D> run(const Plc<D>& plc, Algorithm algorithm, Options options = {}) {
  Run<D> r;
  options.algorithm = algorithm;
  options.statistics = &r.stats;
  r.tri = cdt(plc, options);
  return r;
}

// The cavity sweep equals the sweep sphere on `plc` and decided it itself; returns its statistics.
template <int D>
CdtStatistics expect_same_as_sweep(const Plc<D>& plc, const std::string& what, const Options& options = {}) {
  const Run<D> sphere = run(plc, Algorithm::SweepSphere, options);
  const Run<D> cavity = run(plc, Algorithm::CavitySweep, options);
  EXPECT_EQ(fixtures::simplex_set(cavity.tri), fixtures::simplex_set(sphere.tri)) << what;
  EXPECT_EQ(cavity.tri.points, sphere.tri.points) << what;
  EXPECT_EQ(cavity.stats.algorithm, Algorithm::CavitySweep) << what << ": the whole PLC was swept";
  return cavity.stats;
}

// A far box around `plc`: cavities then stay inside the convex hull (a cavity that reaches the hull
// is swept whole, cavity_plc.h). `skew` moves each corner a little, so that they are not cospherical.
template <int D>
void add_far_box(Plc<D>& plc, double skew = 0) {
  for (int corner = 0; corner < 1 << D; ++corner)
    for (int k = 0; k < D; ++k)
      plc.points.push_back((corner >> (D - 1 - k) & 1 ? 24.0 + k : -20.0 - k) + skew * ((corner * 7 + k * 3) % 11));
}

// Whether the sorted ids `face` are a face of one of `simplices`.
template <int D>
bool is_face(const std::vector<std::array<uint32_t, D + 1>>& simplices, const std::vector<uint32_t>& face) {
  for (std::array<uint32_t, D + 1> s : simplices) {
    std::sort(s.begin(), s.end());
    if (std::includes(s.begin(), s.end(), face.begin(), face.end())) return true;
  }
  return false;
}

// Random points in the unit cube inside a far box, one facet f of their Delaunay triangulation (among
// the random points) as the constraint, and a point p near f's centroid, just off f, such that f is no
// Delaunay face any more but each of its ridges still is. In general position a Delaunay face is
// strongly Delaunay, so by the CDT theorem (paper §1) the PLC has a CDT, and the cavity sweep has a
// cavity to fill.
template <int D>
Plc<D> facet_with_a_point_beside_it(std::mt19937_64& rng, int points) {
  Plc<D> base;
  add_far_box(base, 0.1);
  const uint32_t first = static_cast<uint32_t>(base.num_points());
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < D * points; ++i) base.points.push_back(u(rng));
  const auto simplices = detail::delaunay_simplices<D>(base.points);
  std::uniform_int_distribution<std::size_t> pick(0, simplices.size() - 1);
  for (;;) {
    const auto& s = simplices[pick(rng)];
    if (*std::min_element(s.begin(), s.end()) < first) continue;  // a simplex of the random points only
    Plc<D> plc = base;
    std::vector<uint32_t> facet(s.begin(), s.begin() + D);
    std::sort(facet.begin(), facet.end());
    std::array<double, D> centre{};
    for (const uint32_t v : facet) {
      plc.simplices.push_back(v);
      for (int j = 0; j < D; ++j) centre[j] += plc.point(v)[j] / D;
    }
    for (int j = 0; j < D; ++j) plc.points.push_back(centre[j] + 0.02 * (u(rng) - 0.5));
    const auto after = detail::delaunay_simplices<D>(plc.points);
    if (is_face<D>(after, facet)) continue;
    bool ridges_stay = true;
    for (int k = 0; k < D && ridges_stay; ++k) {
      std::vector<uint32_t> ridge = facet;
      ridge.erase(ridge.begin() + k);
      ridges_stay = is_face<D>(after, ridge);
    }
    if (ridges_stay) return plc;
  }
}

// Where the sweep finds a CDT of `plc`, the cavity sweep finds the same one by itself; where it finds
// none, neither does the cavity sweep. Counts into `tally`: {with a CDT, with missing constraints,
// without a CDT}.
template <int D>
void expect_cavity_sweep_agrees(const Plc<D>& plc, const std::string& what, std::array<int, 3>& tally) {
  bool sweep_found = true;
  try {
    run(plc, Algorithm::SweepSphere);
  } catch (const NoCdtError&) {
    sweep_found = false;
  }
  if (!sweep_found) {
    EXPECT_THROW(run(plc, Algorithm::CavitySweep), NoCdtError) << what;
    ++tally[2];
    return;
  }
  const CdtStatistics stats = expect_same_as_sweep(plc, what);
  ++tally[0];
  tally[1] += stats.missing_constraints > 0;
}

// Random constraints among grid points inside their convex hull (degenerate everywhere), the hull a
// far box.
TEST(CavitySweep, RandomConstraintsInTheConvexHull) {
  std::array<int, 3> tally{};
  for (uint64_t seed = 0; seed < 500; ++seed) {
    std::mt19937_64 rng(seed);
    Plc<3> plc = fixtures::random_constrained_plc<3>(rng, 5, 8, 1 + seed % 2);
    add_far_box(plc);
    expect_cavity_sweep_agrees(plc, "seed " + std::to_string(seed), tally);
  }
  EXPECT_GE(tally[1], 10) << "few PLCs had a constraint missing from the Delaunay tetrahedralization";
  EXPECT_GE(tally[2], 1) << "NoCdtError was never checked";
  std::printf("  %d PLCs with a CDT (%d with missing constraints), %d without\n", tally[0], tally[1], tally[2]);
}

// The same in 2D on grid points (every PSLG has a CDT). In 4D and 5D random constraints among a few
// points mostly have no CDT, and one that has is mostly a Delaunay face: there the constraint is a
// Delaunay facet made missing by a point beside it, which has a CDT (facet_with_a_point_beside_it).
TEST(CavitySweep, RandomConstraintsInOtherDimensions) {
  std::array<int, 3> tally2{}, tally4{}, tally5{};
  for (uint64_t seed = 0; seed < 300; ++seed) {
    std::mt19937_64 rng(seed);
    Plc<2> plc = fixtures::random_constrained_plc<2>(rng, 6, 6, 1 + seed % 3);
    add_far_box(plc);
    expect_cavity_sweep_agrees(plc, "2D seed " + std::to_string(seed), tally2);
  }
  constexpr int kSeeds = 12;
  for (uint64_t seed = 0; seed < kSeeds; ++seed) {
    std::mt19937_64 rng(seed);
    expect_cavity_sweep_agrees(facet_with_a_point_beside_it<4>(rng, 12), "4D seed " + std::to_string(seed), tally4);
    expect_cavity_sweep_agrees(facet_with_a_point_beside_it<5>(rng, 12), "5D seed " + std::to_string(seed), tally5);
  }
  EXPECT_EQ(tally2[2], 0);
  EXPECT_GE(tally2[1], 10) << "few PLCs had a constraint missing from the Delaunay triangulation";
  for (const auto* tally : {&tally4, &tally5}) EXPECT_EQ(*tally, (std::array<int, 3>{kSeeds, kSeeds, 0}));
  std::printf("  2D: %d PLCs with a CDT (%d with missing constraints)\n", tally2[0], tally2[1]);
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
  const detail::DelaunayMesh dt = detail::delaunay_mesh<3>(plc.points);
  ASSERT_EQ(dt.tets.size(), 16u) << "the bipyramid over ABD and BCD";
  const detail::ConstraintFaces faces = detail::constraint_faces<3>(plc, dt, 1);
  EXPECT_EQ(faces.missing, (std::vector<uint32_t>{0, 1}));
  for (std::size_t t = 0; t < 4; ++t)
    for (uint32_t c = 0; c < 2; ++c)
      EXPECT_FALSE((detail::interior_meets<3>({plc.point(dt.tets[4 * t]), plc.point(dt.tets[4 * t + 1]), plc.point(dt.tets[4 * t + 2]),
                                               plc.point(dt.tets[4 * t + 3])},
                                              {plc.point(plc.simplex(c)[0]), plc.point(plc.simplex(c)[1]), plc.point(plc.simplex(c)[2])})));
  EXPECT_EQ(detail::disturbed_simplices<3>(plc, dt, faces.missing, 1).tets, (std::vector<uint8_t>{1, 1, 1, 1}));
  EXPECT_THROW(run(plc, Algorithm::SweepSphere), NoCdtError);
  EXPECT_THROW(run(plc, Algorithm::CavitySweep), NoCdtError);
}

// disturbed_simplices against its definition, tetrahedron by tetrahedron: a tetrahedron is disturbed
// when a missing constraint meets its interior or meets one of its facets other than in the face
// their shared vertices span. The search looks only around each constraint and skips, without the
// full test, a tetrahedron strictly on one side of the constraint's plane but for shared vertices;
// a brute force over every pair checks both. Integer points in a 5^3 grid: many coplanar and
// cospherical ones, constraints in Delaunay facets' planes.
TEST(CavitySweep, DisturbedSimplicesAreThoseTheDefinitionNames) {
  int plcs = 0, disturbed = 0, clear = 0;
  for (uint64_t seed = 0; seed < 250; ++seed) {
    std::mt19937_64 rng(seed);
    const Plc<3> plc = fixtures::random_constrained_plc<3>(rng, 10, 8, 8);
    const detail::DelaunayMesh dt = detail::delaunay_mesh<3>(plc.points);
    const detail::ConstraintFaces faces = detail::constraint_faces<3>(plc, dt, 1);
    if (faces.missing.empty()) continue;
    ++plcs;
    const detail::Disturbed found = detail::disturbed_simplices<3>(plc, dt, faces.missing, 1);
    ASSERT_EQ(found.tets.size(), dt.tets.size() / 4) << "seed " << seed;
    for (std::size_t t = 0; t < dt.tets.size() / 4; ++t) {
      const uint32_t* s = &dt.tets[4 * t];
      bool expected = false;
      for (const uint32_t m : faces.missing) {
        const uint32_t* c = plc.simplex(m);
        const std::array<const double*, 3> c_points{plc.point(c[0]), plc.point(c[1]), plc.point(c[2])};
        const std::array<uint32_t, 3> c_ids{c[0], c[1], c[2]};
        expected = detail::interior_meets<3>({plc.point(s[0]), plc.point(s[1]), plc.point(s[2]), plc.point(s[3])}, c_points);
        for (int i = 0; i < 4 && !expected; ++i) {
          const detail::FacetKey<3> f = detail::facet_key<3>(s, i);
          expected = detail::improper_intersection<3>({plc.point(f[0]), plc.point(f[1]), plc.point(f[2])}, f, c_points, c_ids);
        }
        if (expected) break;
      }
      ASSERT_EQ(found.tets[t] != 0, expected) << "seed " << seed << ", tetrahedron " << t;
      ++(expected ? disturbed : clear);
    }
  }
  EXPECT_GE(plcs, 100);
  EXPECT_GE(disturbed, 500);
  std::printf("  %d PLCs with missing constraints: %d tetrahedra disturbed, %d not\n", plcs, disturbed, clear);
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

// With failed_edges, cavity_cdt reports where a cavity finds no CDT (lazy Steiner refinement splits
// there, cdt.cpp): Schönhardt's prism has none, and its cavity is the whole prism; a box in a box
// has one, and nothing is reported.
TEST(CavitySweep, ReportsTheCavitiesWithoutACdt) {
  const Plc<3> prism = fixtures::twisted_prism(0.5);
  CdtStatistics stats;
  std::vector<std::array<uint32_t, 2>> failed;
  EXPECT_FALSE(detail::cavity_cdt<3>(prism, {}, stats, nullptr, &failed).has_value());
  ASSERT_FALSE(failed.empty());
  std::set<uint32_t> ends;
  for (const auto& [a, b] : failed) ends.insert({a, b});
  for (uint32_t v = 0; v < 6; ++v) EXPECT_TRUE(ends.count(v)) << "prism vertex " << v << " is in no reported edge";
  Plc<3> nested;
  fixtures::add_box(nested, {0, 0, 0}, {4, 4, 4}, true);
  fixtures::add_box(nested, {1, 1, 1}, {2, 3, 2}, false);
  failed.clear();
  const std::optional<Triangulation<3>> tri = detail::cavity_cdt<3>(nested, {}, stats, nullptr, &failed);
  EXPECT_TRUE(tri.has_value());
  EXPECT_TRUE(failed.empty());
}

// A cavity's sweep (sweep_cavity): the sweep plane along the axis where it is thinnest, the axes
// turned for it. A flat box with points inside and a refined comb (a PLC with a CDT), each thinnest
// along each axis in turn (coordinates permuted cyclically: the same shape turned): the sweep
// sphere's CDT of the same PLC, each simplex positively oriented in the PLC's own coordinates
// (validate()), the plane along that axis.
TEST(CavitySweep, CavitiesSweptAlongTheirThinnestAxisAsTheSphereSweepsThem) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  Plc<3> box = fixtures::unit_cube_surface();
  for (int i = 0; i < 3 * 150; ++i) box.points.push_back(u(rng));
  for (std::size_t x = 0; x < box.num_points(); ++x) box.points[3 * x + 2] *= 0.125;  // thinnest along z
  Plc<3> comb;  // thinnest along z: 5 by 4 by 2
  Options refine = mesh_defaults();
  refine.remove_steiner_points = false;
  cdt(fixtures::extruded_columns({0, 1, 1.2, 3, 3.1, 5}, {3, 0.5, 3, 0.2, 4}, 2), refine, &comb);
  int swept = 0;
  for (const auto& [what, plc] : {std::pair{"flat box with points", box}, std::pair{"refined comb", comb}})
    for (int axis = 0; axis < 3; ++axis) {
      Plc<3> turned = plc;  // z moved to `axis`
      for (std::size_t x = 0; x < plc.num_points(); ++x)
        for (int k = 0; k < 3; ++k) turned.points[3 * x + (k + axis + 1) % 3] = plc.points[3 * x + k];
      CdtStatistics stats;
      const Triangulation<3> sphere = detail::sweep_cdt<3>(turned, detail::seed_simplex(turned), Options{}, stats);
      int along = -1;
      Triangulation<3> plane = detail::sweep_cavity<3>(turned, Options{}, stats, &along);
      EXPECT_EQ(along, axis) << what;
      EXPECT_EQ(fixtures::simplex_set(plane), fixtures::simplex_set(sphere)) << what << ", thinnest along axis " << axis;
      compute_neighbors(plane);
      const ValidationReport report = validate(plane, turned);
      EXPECT_TRUE(report.ok()) << what << ", thinnest along axis " << axis << "\n" << report.summary();
      swept += report.ok();
    }
  EXPECT_EQ(swept, 6);
}

}  // namespace
