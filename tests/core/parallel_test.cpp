// The parallel parts (core/src/parallel.h) give the answer one thread gives: the PLC check's
// problems, validate()'s failures (in the same order, the same counts), the perturbation ties counted
// on the caller's thread, and cdt()'s triangulation. The inputs are big enough to be cut into parts
// (parallel.h: kItemsPerThread items a part), which each test checks first.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "cad_noise.h"
#include "cavity/disturbed.h"
#include "edit/remove_steiner.h"
#include "steiner/refine.h"
#include "steiner/facet_groups.h"
#include "parallel.h"
#include "delaunay/delaunay.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/predicates/stats.h"
#include "test_shapes.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

constexpr unsigned kMany = 4;  // threads: more than this machine has is fine, the parts are the point

// A comb with many teeth: a facet-bounded surface of a few thousand triangles.
Plc<3> comb(int teeth) {
  std::vector<double> xs{0}, tops;
  for (int i = 0; i < teeth; ++i) {
    xs.push_back(xs.back() + 1);
    tops.push_back(1 + (i % 7) * 0.37);
  }
  return fixtures::extruded_columns(xs, tops, 3);
}

// `copies` copies of `plc`, each shifted by `step` along x: overlapping bodies when step is small.
Plc<3> copies_of(const Plc<3>& plc, int copies, double step) {
  Plc<3> all;
  for (int c = 0; c < copies; ++c) {
    const uint32_t base = static_cast<uint32_t>(all.num_points());
    for (std::size_t i = 0; i < plc.num_points(); ++i)
      all.points.insert(all.points.end(), {plc.point(i)[0] + c * step, plc.point(i)[1], plc.point(i)[2]});
    for (const uint32_t v : plc.simplices) all.simplices.push_back(base + v);
    all.exterior.insert(all.exterior.end(), plc.exterior.begin(), plc.exterior.end());
  }
  return all;
}

// WorkerPool::run calls `while_waiting` on the calling thread while it waits for a helper still at
// work (the cavity sweep reports progress there, so that a cancel is heard while a helper sweeps a
// large cavity). Deterministic: the caller's job holds it until the helper has started the other
// job, and the helper's job ends only once the caller has been called back (the deadline only keeps
// a failure from hanging).
TEST(Parallel, WorkerPoolCallsTheCallerBackWhileItWaits) {
  detail::WorkerPool pool(1);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> helper_started{false}, called_back{false}, gave_up{false};
  std::atomic<int> called_elsewhere{0};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  const auto wait_for = [&](const std::atomic<bool>& flag) {
    while (!flag) {
      if (std::chrono::steady_clock::now() > deadline) return void(gave_up = true);
      std::this_thread::yield();
    }
  };
  const std::function<void(std::size_t)> job = [&](std::size_t) {
    if (std::this_thread::get_id() == caller) {
      wait_for(helper_started);
    } else {
      helper_started = true;
      wait_for(called_back);
    }
  };
  pool.run(2, job, [&] {
    if (std::this_thread::get_id() != caller) ++called_elsewhere;
    called_back = true;
  });
  EXPECT_TRUE(helper_started);
  EXPECT_TRUE(called_back);
  EXPECT_FALSE(gave_up);
  EXPECT_EQ(called_elsewhere, 0);
}

TEST(Parallel, PlcCheckFindsTheSameProblemsInTheSameOrder) {
  const Plc<3> overlapping = copies_of(comb(400), 3, 0.5);  // intersecting everywhere
  ASSERT_GT(detail::parts_for(overlapping.num_simplices(), kMany), 1u);
  uint64_t total_one = 0, total_many = 0;
  const auto one = find_problems<3>(overlapping, 10, &total_one, nullptr, 1);
  const auto many = find_problems<3>(overlapping, 10, &total_many, nullptr, kMany);
  EXPECT_GT(total_one, 1000u);
  EXPECT_EQ(total_many, total_one);
  ASSERT_EQ(many.size(), one.size());
  for (std::size_t k = 0; k < one.size(); ++k) EXPECT_EQ(many[k].message, one[k].message);
  EXPECT_TRUE(find_problems<3>(comb(400), 10, nullptr, nullptr, kMany).empty());
}

TEST(Parallel, ValidateReportsTheSameFailuresAndTies) {
  // A grid of points: cospherical ties everywhere, so the perturbation decides many local tests.
  Plc<3> grid;
  for (int x = 0; x < 16; ++x)
    for (int y = 0; y < 16; ++y)
      for (int z = 0; z < 16; ++z) grid.points.insert(grid.points.end(), {double(x), double(y), double(z)});
  Triangulation<3> tri = cdt(grid);
  ASSERT_GT(detail::parts_for(tri.num_simplices(), kMany), 1u);
  const auto ties = [&](unsigned threads) {
    const uint64_t before = predicates::perturbation_ties_on_this_thread();
    EXPECT_TRUE(validate(tri, grid, ValidationLevel::Full, threads).ok());
    return predicates::perturbation_ties_on_this_thread() - before;
  };
  const uint64_t ties_one = ties(1);
  EXPECT_GT(ties_one, 0u);
  EXPECT_EQ(ties(kMany), ties_one);

  // Break it: every 97th simplex turned inside out, which the orientation, facet-side and local
  // Delaunay tests all report, far more often than the 10 failures a check lists.
  for (std::size_t t = 0; t < tri.num_simplices(); t += 97) std::swap(tri.simplices[4 * t], tri.simplices[4 * t + 1]);
  const ValidationReport one = validate(tri, grid, ValidationLevel::Full, 1);
  const ValidationReport many = validate(tri, grid, ValidationLevel::Full, kMany);
  EXPECT_GT(one.count("orientation"), 10u);
  EXPECT_EQ(many.counts, one.counts);
  ASSERT_EQ(many.failures.size(), one.failures.size());
  for (std::size_t k = 0; k < one.failures.size(); ++k) {
    EXPECT_EQ(many.failures[k].check, one.failures[k].check);
    EXPECT_EQ(many.failures[k].detail, one.failures[k].detail);
  }
}

// cdt() with one thread and with several: the same simplices, for the cavity sweep (whose Delaunay
// tetrahedralization runs beside the check when there is a second thread, and whose cavities are
// swept on the threads: cavity_cdt.cpp) and the sweep; the comb and the noisy fins (whose refined PLC
// has cavities) with the converter's options, the deletion pass off to keep it short.
TEST(Parallel, CdtIsTheSameForAnyNumberOfThreads) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  Plc<3> points;
  for (int i = 0; i < 3 * 6000; ++i) points.points.push_back(u(rng));
  for (const auto& [what, plc] : {std::pair{"random points", points}, std::pair{"comb", comb(600)}, std::pair{"noisy fins", sweepcdt::testing::noisy_fins(7, 12)}}) {
    for (const Algorithm algorithm : {Algorithm::CavitySweep, Algorithm::SweepSphere}) {
      Options one = std::string(what) != "random points" ? mesh_defaults() : Options{};
      one.remove_steiner_points = false;
      Options many = one;
      one.algorithm = many.algorithm = algorithm;
      one.threads = 1;
      many.threads = kMany;
      CdtStatistics stats, stats_one;
      many.statistics = &stats;
      one.statistics = &stats_one;
      const Triangulation<3> a = cdt(plc, one), b = cdt(plc, many);
      EXPECT_EQ(fixtures::simplex_set(b), fixtures::simplex_set(a)) << what << " " << to_string(algorithm);
      EXPECT_EQ(b.regions.size(), a.regions.size());
      EXPECT_EQ(stats.algorithm, algorithm) << what;
      if (algorithm == Algorithm::CavitySweep && std::string(what) == "noisy fins") {
        EXPECT_GT(stats_one.cavity_tetrahedra, 100u) << "no cavities: their sweeps on threads are not exercised";
        EXPECT_EQ(b.simplices, a.simplices) << "cavities assembled in another order";
        EXPECT_EQ(stats.queue_pops, stats_one.queue_pops);
        EXPECT_EQ(stats.drop_moves, stats_one.drop_moves);
      }
    }
  }
}

// Refinement inserts a large pass's points into the tetrahedralization on a helper thread while it
// splits the surface's triangles (refine.h, kPointsBeside): the refined PLC one thread makes, point
// for point and triangle for triangle, and the same tetrahedralization. A revolved surface with a
// waist and noise, every triangle a facet: refinement's first pass splits each segment that is no
// edge of the input points' Delaunay tetrahedralization, counted here, enough for the helper.
TEST(Parallel, RefinementIsTheSameForAnyNumberOfThreads) {
  Plc<3> vase;
  std::vector<std::array<double, 2>> profile;
  for (int k = 0; k < 13; ++k) profile.push_back({12 + 6 * (k - 6) * (k - 6) / 36.0, 3.5 * k});  // a waist: not convex
  fixtures::add_revolved(vase, profile, 360, 0, 42);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-1e-2, 1e-2);
  for (double& x : vase.points) x += jitter(rng);  // a scan's noise: many edges of the waist's strips not Delaunay
  detail::DelaunayEdges input_delaunay(vase.points);
  std::set<uint64_t> first_pass;
  for (std::size_t t = 0; t < vase.num_simplices(); ++t)
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = vase.simplex(t)[i], b = vase.simplex(t)[(i + 1) % 3];
      if (!input_delaunay.has_edge(a, b)) first_pass.insert(detail::edge_key(a, b));
    }
  ASSERT_GE(first_pass.size(), detail::kPointsBeside) << "the first pass is too small for the helper";
  Options one = mesh_defaults();
  one.facets = FacetMode::Triangles;
  Options many = one;
  one.threads = 1;
  many.threads = kMany;
  const detail::RefinedPlc a = detail::refine(vase, one), b = detail::refine(vase, many);
  std::cout << "[ vase ] " << first_pass.size() << " points in the first pass, " << a.steiner_on.size() << " in all\n";
  EXPECT_GT(a.steiner_on.size(), first_pass.size());
  EXPECT_EQ(b.plc.points, a.plc.points);
  EXPECT_EQ(b.plc.simplices, a.plc.simplices);
  EXPECT_EQ(b.steiner_on, a.steiner_on);
  EXPECT_EQ(b.flips, a.flips);
  ASSERT_TRUE(a.delaunay && b.delaunay);
  EXPECT_EQ(b.delaunay->tets, a.delaunay->tets);
}

// side_by_side() runs its second job on another thread when asked, and rethrows the first job's
// exception before the second's, as one thread running them in order would meet them.
TEST(Parallel, SideBySideRunsTheSecondJobOnAHelperAndRethrowsInOrder) {
  std::thread::id first_on, second_on;
  detail::side_by_side(true, [&] { first_on = std::this_thread::get_id(); }, [&] { second_on = std::this_thread::get_id(); });
  EXPECT_EQ(first_on, std::this_thread::get_id());
  EXPECT_NE(second_on, std::this_thread::get_id());
  detail::side_by_side(false, [&] { first_on = std::this_thread::get_id(); }, [&] { second_on = std::this_thread::get_id(); });
  EXPECT_EQ(second_on, std::this_thread::get_id());
  for (const bool two : {false, true}) {
    bool second_ran = false;
    try {
      detail::side_by_side(two, [] { throw std::runtime_error("first"); }, [&] {
        second_ran = true;
        throw std::logic_error("second");
      });
      ADD_FAILURE() << "nothing rethrown";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "first");
    }
    EXPECT_EQ(second_ran, two) << "one thread stops at the first error; two run both";
    try {
      detail::side_by_side(two, [] {}, [] { throw std::logic_error("second"); });
      ADD_FAILURE() << "nothing rethrown";
    } catch (const std::logic_error& e) {
      EXPECT_STREQ(e.what(), "second");
    }
  }
}

// The cavity sweep's constraints among the Delaunay facets (cavity/disturbed.h), looked up in parts:
// per facet, the constraint a brute-force map of the constraints' vertex sets names, on both sides of
// it; the missing ones; the same on one thread and on several.
TEST(Parallel, ConstraintFacesAsABruteForceLookupFindsThem) {
  const Plc<3> plc = comb(600);
  const detail::DelaunayMesh dt = detail::delaunay_mesh<3>(plc.points);
  const std::size_t tets = dt.tets.size() / 4;
  ASSERT_GT(detail::parts_for(tets, kMany), 1u);
  std::map<std::array<uint32_t, 3>, uint32_t> constraint;
  for (uint32_t c = 0; c < plc.num_simplices(); ++c) {
    std::array<uint32_t, 3> key{plc.simplex(c)[0], plc.simplex(c)[1], plc.simplex(c)[2]};
    std::sort(key.begin(), key.end());
    constraint[key] = c;
  }
  std::vector<uint32_t> expected(4 * tets, kNone);
  std::vector<char> present(plc.num_simplices(), 0);
  for (std::size_t t = 0; t < tets; ++t)
    for (int i = 0; i < 4; ++i) {
      std::array<uint32_t, 3> key;
      for (int k = 0, r = 0; k < 4; ++k)
        if (k != i) key[r++] = dt.tets[4 * t + k];
      std::sort(key.begin(), key.end());
      if (const auto it = constraint.find(key); it != constraint.end()) expected[4 * t + i] = it->second, present[it->second] = 1;
    }
  std::vector<uint32_t> missing;
  for (uint32_t c = 0; c < plc.num_simplices(); ++c)
    if (!present[c]) missing.push_back(c);
  ASSERT_GT(std::count(present.begin(), present.end(), 1), 1000);
  for (const unsigned threads : {1u, kMany}) {
    const detail::ConstraintFaces faces = detail::constraint_faces(plc, dt, threads);
    EXPECT_EQ(faces.of_facet, expected) << threads << " threads";
    EXPECT_EQ(faces.missing, missing) << threads << " threads";
  }
}

// The cavity sweep's disturbed simplices (cavity/disturbed.h), searched from the missing constraints
// in parts: the same simplices, and the same first one per constraint, as on one thread. The PLC is
// what the converter sweeps on CAD parts: noisy fins refined with Steiner points, whose bent facets
// miss many Delaunay faces.
TEST(Parallel, DisturbedSimplicesAsOneThreadFindsThem) {
  const Plc<3> fins = sweepcdt::testing::noisy_fins(7, 30);
  Options options = mesh_defaults();
  options.remove_steiner_points = false;
  Plc<3> refined;
  cdt(fins, options, &refined);
  const detail::DelaunayMesh dt = detail::delaunay_mesh<3>(refined.points);
  const detail::ConstraintFaces faces = detail::constraint_faces<3>(refined, dt, 1);
  std::cout << "[ fins ] " << faces.missing.size() << " of " << refined.num_simplices() << " constraints missing\n";
  const detail::Disturbed one = detail::disturbed_simplices<3>(refined, dt, faces.missing, 1);
  const detail::Disturbed many = detail::disturbed_simplices<3>(refined, dt, faces.missing, kMany);
  ASSERT_GT(detail::parts_for(faces.missing.size(), kMany, detail::kConstraintsPerThread), 1u) << "too few to search in parts";
  ASSERT_EQ(one.first.size(), faces.missing.size());
  EXPECT_GT(std::count(one.tets.begin(), one.tets.end(), 1), 100);
  EXPECT_EQ(many.tets, one.tets);
  EXPECT_EQ(many.first, one.first);
}

// The deletion pass (remove_steiner.h) works deletions out on several threads and applies them in
// the order of one: the same points deleted, the same tetrahedra in the same order.
TEST(Parallel, SteinerPointsDeletedAsOneThreadDeletesThem) {
  const Plc<3> fins = sweepcdt::testing::noisy_fins(7, 12);
  Options one = mesh_defaults(), many = mesh_defaults();
  one.threads = 1;
  many.threads = kMany;
  CdtStatistics stats_one, stats_many;
  one.statistics = &stats_one;
  many.statistics = &stats_many;
  const Triangulation<3> a = cdt(fins, one), b = cdt(fins, many);
  std::cout << "[ fins ] " << stats_one.steiner_points + stats_one.steiner_points_removed << " Steiner points, "
            << stats_one.steiner_points_removed << " deleted again\n";
  ASSERT_GE(stats_one.steiner_points + stats_one.steiner_points_removed, detail::kPointsForThreads) << "too few to delete them on threads";
  ASSERT_GT(stats_one.steiner_points_removed, 20u);
  EXPECT_EQ(stats_many.steiner_points_removed, stats_one.steiner_points_removed);
  EXPECT_EQ(b.points, a.points);
  EXPECT_EQ(b.steiner_on, a.steiner_on);
  EXPECT_EQ(b.simplices, a.simplices);
  EXPECT_EQ(b.regions, a.regions);
}

// A part that throws: the error reaches the caller after every part ended.
TEST(Parallel, AnExceptionInAPartReachesTheCaller) {
  std::vector<int> done(4 * detail::kItemsPerThread, 0);
  EXPECT_THROW(detail::for_each_part(done.size(), kMany,
                                     [&](std::size_t part, std::size_t begin, std::size_t end) {
                                       for (std::size_t i = begin; i < end; ++i) done[i] = 1;
                                       if (part == 2) throw std::runtime_error("part 2");
                                     }),
               std::runtime_error);
  EXPECT_EQ(std::count(done.begin(), done.end(), 1), static_cast<long>(done.size()));
}

}  // namespace
