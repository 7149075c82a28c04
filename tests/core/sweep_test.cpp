// SWEEPCDT (sweep sphere and sweep plane) against gift-wrapping and brute force: identical simplex
// sets on random and degenerate inputs in D = 2..5, facet-bounded shapes, and NoCdtError.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <string>
#include <thread>

#include "brute_force_delaunay.h"
#include "cad_noise.h"
#include "off_reader.h"
#include "sweepcdt/cdt.h"
#include "triangulation_util.h"
#include "sweepcdt/validate.h"
#include "test_shapes.h"

using namespace sweepcdt;

namespace {

template <int D>
Triangulation<D> run(const Plc<D>& plc, Algorithm algorithm, CdtStatistics* stats = nullptr) {
  Options options;
  options.algorithm = algorithm;
  options.statistics = stats;
  return cdt(plc, options);
}

// All algorithms give the same simplices, and validate() accepts them.
template <int D>
void expect_agreement(const Plc<D>& plc, const std::string& what) {
  const auto reference = run(plc, Algorithm::GiftWrap);
  for (Algorithm a : {Algorithm::SweepSphere, Algorithm::SweepPlane, Algorithm::CavitySweep}) {
    Triangulation<D> tri;
    try {
      tri = run(plc, a);
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << " " << to_string(a) << ": " << e.what();
      continue;
    }
    EXPECT_EQ(fixtures::simplex_set(tri), fixtures::simplex_set(reference)) << what << " " << to_string(a);
    const auto report = validate(tri, plc);
    EXPECT_TRUE(report.ok()) << what << " " << to_string(a) << "\n" << report.summary();
  }
}

template <int D>
void random_points(int count, int seeds, bool grid) {
  int compared = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(31 * D + seed);
    std::uniform_int_distribution<int> coordinate(0, grid ? 2 : 1 << 30);
    std::set<std::vector<double>> seen;
    Plc<D> plc;
    while (static_cast<int>(seen.size()) < count) {
      std::vector<double> p(D);
      for (auto& x : p) x = coordinate(rng);
      if (seen.insert(p).second) plc.points.insert(plc.points.end(), p.begin(), p.end());
    }
    if (grid && fixtures::brute_force_delaunay<D>(plc.points).num_simplices() == 0) continue;  // flat
    expect_agreement(plc, "D=" + std::to_string(D) + (grid ? " grid" : " random") + " seed " + std::to_string(seed));
    ++compared;
  }
  EXPECT_GE(compared, seeds / 2) << "most point sets were flat: the comparison covers little";
}

TEST(Sweep, RandomPoints2D) { random_points<2>(200, 10, false); }
TEST(Sweep, RandomPoints3D) { random_points<3>(200, 6, false); }
TEST(Sweep, RandomPoints4D) { random_points<4>(50, 3, false); }
TEST(Sweep, RandomPoints5D) { random_points<5>(24, 2, false); }
TEST(Sweep, GridPoints2D) { random_points<2>(9, 20, true); }
TEST(Sweep, GridPoints3D) { random_points<3>(14, 20, true); }
TEST(Sweep, GridPoints4D) { random_points<4>(12, 10, true); }

TEST(Sweep, FacetBoundedShapes) {
  expect_agreement(fixtures::unit_cube_surface(), "unit cube");
  Plc<3> cavity;
  fixtures::add_box(cavity, {0, 0, 0}, {4, 4, 4}, true);
  fixtures::add_box(cavity, {1, 1, 1}, {2, 3, 2}, false);
  expect_agreement(cavity, "cube with cavity");
  Plc<3> two;
  fixtures::add_box(two, {0, 0, 0}, {1, 1, 1}, true);
  fixtures::add_box(two, {3, 0, 0}, {4, 2, 1}, true);
  expect_agreement(two, "two cubes");
  Plc<2> holed;
  holed.points = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 1, 3, 3, 3, 3, 1, 2, 0.5};
  holed.simplices = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  holed.exterior.assign(8, ExteriorSide::Negative);
  expect_agreement(holed, "square with hole");
  Plc<3> vertex;  // two tetrahedra meeting at one vertex: a non-manifold domain
  vertex.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1};
  fixtures::add_tetrahedron(vertex, {0, 1, 2, 3});
  fixtures::add_tetrahedron(vertex, {0, 4, 5, 6});
  expect_agreement(vertex, "two tetrahedra sharing a vertex");
  if (const auto ico = fixtures::read_off_surface(std::string(SWEEPCDT_SHARED_DATA) + "/off/icosahedron.off"))
    expect_agreement(*ico, "icosahedron");
}

TEST(Sweep, SchonhardtHasNoCdt) {
  for (double twist : {0.0, 0.5})
    for (Algorithm a : {Algorithm::SweepSphere, Algorithm::SweepPlane, Algorithm::CavitySweep})
      EXPECT_THROW(run(fixtures::twisted_prism(twist), a), NoCdtError) << to_string(a) << " twist " << twist;
}

TEST(Sweep, StatisticsAreReported) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  Plc<3> plc;
  for (int i = 0; i < 3 * 500; ++i) plc.points.push_back(u(rng));
  CdtStatistics stats;
  const auto tri = run(plc, Algorithm::SweepPlane, &stats);
  EXPECT_EQ(stats.algorithm, Algorithm::SweepSphere);  // a convex hull domain is swept by the sphere
  EXPECT_EQ(stats.simplices, tri.num_simplices());
  EXPECT_GE(stats.queue_pops, stats.simplices);
  EXPECT_GT(stats.queue_pushes, 0u);
}

// Progress reports (vertices reached of all vertices) and cancellation, for both algorithm families.
TEST(Progress, ReportsAndCancels) {
  for (const auto& [algorithm, points] :
       {std::pair{Algorithm::GiftWrap, 800}, std::pair{Algorithm::SweepSphere, 4000}, std::pair{Algorithm::CavitySweep, 4000}}) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(0, 1);
    Plc<3> plc;
    for (int i = 0; i < 3 * points; ++i) plc.points.push_back(u(rng));
    int calls = 0;
    Options options;
    options.algorithm = algorithm;
    options.progress = [&](const Progress& p) {
      ++calls;
      EXPECT_LE(p.done, p.total);
      return true;
    };
    EXPECT_NO_THROW(cdt(plc, options)) << to_string(algorithm);
    EXPECT_GT(calls, 0) << to_string(algorithm);
    options.progress = [](const Progress&) { return false; };
    EXPECT_THROW(cdt(plc, options), CancelledError) << to_string(algorithm);
  }
}

// Cancelling the default pipeline (refinement, with its Delaunay tetrahedralization on a helper
// thread, Steiner points, their deletion) at each of its reports, on two threads: CancelledError every
// time, and nothing left running (a helper thread never joined would end the process).
TEST(Progress, CancelsTheDefaultPipelineAtEveryReport) {
  const Plc<3> plc = fixtures::twisted_prism(0.6);  // no CDT without Steiner points
  Options options = mesh_defaults();
  options.threads = 2;
  int reports = 0;
  options.progress = [&](const Progress&) { return ++reports, true; };
  ASSERT_NO_THROW(cdt(plc, options));
  ASSERT_GT(reports, 1);
  for (int stop_at = 1; stop_at <= reports; ++stop_at) {
    int calls = 0;
    options.progress = [&](const Progress&) { return ++calls < stop_at; };
    EXPECT_THROW(cdt(plc, options), CancelledError) << "cancelled at report " << stop_at;
  }
}

// The cavity sweep sweeps its cavities on the threads (cavity_cdt.cpp), and the deletion pass plans
// deletions on them: progress is still reported from the calling thread only (a host's callback —
// Python, FreeCAD, MeshLab — need not be thread-safe), and cancelling while the cavities are swept
// ("cavities": reported after each the calling thread sweeps, and once when all are) stops them.
// Noisy fins: many cavities, many deletions.
TEST(Progress, ReportedFromTheCallingThreadOnlyAndCancelsTheCavities) {
  const Plc<3> fins = sweepcdt::testing::noisy_fins(7, 30);
  Options options = mesh_defaults();
  options.threads = 4;
  CdtStatistics stats;
  options.statistics = &stats;
  const std::thread::id caller = std::this_thread::get_id();
  int reports = 0, elsewhere = 0, cavities = 0;
  options.progress = [&](const Progress& p) {
    ++reports;
    if (std::this_thread::get_id() != caller) ++elsewhere;
    if (std::string(p.phase) == "cavities") {
      ++cavities;
      EXPECT_LE(p.done, p.total);
    }
    return true;
  };
  ASSERT_NO_THROW(cdt(fins, options));
  EXPECT_GT(reports, 0);
  EXPECT_EQ(elsewhere, 0);
  EXPECT_GT(cavities, 0);
  EXPECT_GT(stats.cavity_tetrahedra, 100u) << "no cavities: their sweeps on threads are not exercised";
  EXPECT_GT(stats.steiner_deletions_tried, 1024u) << "too few deletions to plan them on threads";
  options.progress = [](const Progress& p) { return std::string(p.phase) != "cavities"; };
  EXPECT_THROW(cdt(fins, options), CancelledError);
}

// Refinement's Delaunay tetrahedralization reports progress ("Delaunay") and can be cancelled there,
// on one thread and with the helper thread that computes it while the facets are grouped.
TEST(Progress, RefinementsTetrahedralizationReportsAndCancels) {
  const Plc<3> plc = fixtures::grid_box_surface(24);  // 3458 points: reports every 1024 insertions
  ASSERT_GT(plc.num_points(), 2048u);
  for (const unsigned threads : {1u, 2u}) {
    Options options = mesh_defaults();
    options.threads = threads;
    int reports = 0;
    options.progress = [&](const Progress& p) {
      if (std::string(p.phase) == "Delaunay") {
        ++reports;
        EXPECT_LE(p.done, p.total);
        EXPECT_EQ(p.total, plc.num_points());
      }
      return true;
    };
    ASSERT_NO_THROW(cdt(plc, options)) << threads;
    EXPECT_GT(reports, 0) << threads << " threads";
    options.progress = [](const Progress& p) { return std::string(p.phase) != "Delaunay"; };
    EXPECT_THROW(cdt(plc, options), CancelledError) << threads << " threads";
  }
}

}  // namespace
