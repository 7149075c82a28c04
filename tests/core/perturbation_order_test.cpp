// Paper §6: "The order in which the vertices are perturbed can determine whether or not a
// triangulation is discovered." The sequence of sweepcdt/perturbation_order.h, validate() under a
// recorded order, and cdt() trying later orders when the vertex-id order leaves an exactly
// cospherical PLC without a CDT — with every algorithm, in D = 3..5 — but not when a run met no tie.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <optional>
#include <set>
#include <string>

#include "sweepcdt/cdt.h"
#include "sweepcdt/perturbation_order.h"
#include "sweepcdt/validate.h"
#include "test_shapes.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

// Every algorithm: sweepcdt::kAlgorithms (the cavity sweep, the two sweeps, gift-wrapping).

bool is_permutation_of_ids(const std::vector<uint32_t>& rank) {
  std::vector<uint32_t> sorted = rank;
  std::sort(sorted.begin(), sorted.end());
  for (uint32_t i = 0; i < sorted.size(); ++i)
    if (sorted[i] != i) return false;
  return true;
}

TEST(PerturbationOrder, EveryOrderIsAPermutationAndOrderZeroIsTheIds) {
  const Plc<3> plc = fixtures::grid_box_surface(2);
  std::vector<uint32_t> ids(plc.num_points());
  std::iota(ids.begin(), ids.end(), 0u);
  EXPECT_EQ(perturbation_rank(plc, 0), ids);
  std::set<std::vector<uint32_t>> distinct;
  for (int order = 0; order < kPerturbationOrders + 4; ++order) {
    const auto rank = perturbation_rank(plc, order);
    EXPECT_TRUE(is_permutation_of_ids(rank)) << "order " << order;
    EXPECT_EQ(rank, perturbation_rank(plc, order)) << "order " << order << " is not reproducible";
    distinct.insert(rank);
  }
  EXPECT_EQ(distinct.size(), std::size_t(kPerturbationOrders + 4));
}

// Meshes written under a later order are checked by recomputing it (sweepcdt check), so the
// sequence must not change between versions or platforms: pinned here, to values computed by an
// independent Python SplitMix64 + Fisher–Yates (whose first outputs for seed 0, e220a8397b1dcdaf
// 6e789e6aa1b965f4, are the reference generator's).
TEST(PerturbationOrder, PseudoRandomOrdersArePinned) {
  Plc<2> plc;
  for (int i = 0; i < 10; ++i) plc.points.insert(plc.points.end(), {double(i), double(i * i)});
  EXPECT_EQ(perturbation_rank(plc, 6), (std::vector<uint32_t>{4, 6, 9, 5, 3, 8, 7, 1, 2, 0}));
  EXPECT_EQ(perturbation_rank(plc, 7), (std::vector<uint32_t>{4, 1, 7, 6, 5, 2, 8, 9, 0, 3}));
}

TEST(PerturbationOrder, MostConstrainedFirstThenCoordinates) {
  Plc<2> plc;
  plc.points = {0, 0, 2, 0, 1, 1, 1, -1};  // a diamond: 0 and 1 left and right, 2 up, 3 down
  plc.simplices = {2, 3, 0, 2, 3, 1};       // point 2 and 3 on two segments, 0 and 1 on one
  EXPECT_EQ(perturbation_rank(plc, 1), (std::vector<uint32_t>{2, 3, 0, 1}));
  EXPECT_EQ(perturbation_rank(plc, 2), (std::vector<uint32_t>{0, 3, 2, 1}));  // x, then y ascending
  EXPECT_EQ(perturbation_rank(plc, 3), (std::vector<uint32_t>{0, 3, 1, 2}));  // x ascending, y descending
}

// validate() perturbs by tri.perturbation_rank and rejects a malformed one.
TEST(PerturbationOrder, ValidateChecksTheRank) {
  const Plc<3> cube = fixtures::unit_cube_surface();
  Triangulation<3> tri = cdt(cube);
  ASSERT_TRUE(validate(tri, cube).ok());
  tri.perturbation_rank = {0, 1, 2};
  EXPECT_EQ(validate(tri, cube).count("shape"), 1u);
  tri.perturbation_rank = {0, 1, 2, 3, 4, 5, 6, 6};
  EXPECT_EQ(validate(tri, cube).count("shape"), 1u);
}

struct Retried {
  std::set<std::vector<uint32_t>> simplices;
  uint32_t order = 0;
};

// A CDT of `plc` exactly as given, found under a later perturbation order: validate()-clean with its
// rank, not without it.
template <int D>
Retried expect_cdt_in_a_later_order(const Plc<D>& plc, Algorithm algorithm, const std::string& what) {
  Options options;
  options.algorithm = algorithm;
  CdtStatistics stats;
  options.statistics = &stats;
  Triangulation<D> tri;
  try {
    tri = cdt(plc, options);
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ", " << to_string(algorithm) << ": " << e.what();
    return {};
  }
  const std::string name = what + ", " + to_string(algorithm);
  EXPECT_EQ(tri.num_input_points, plc.num_points()) << name;
  EXPECT_EQ(tri.num_points(), plc.num_points()) << name << ": Steiner points";
  EXPECT_TRUE(tri.steiner_on.empty()) << name;
  EXPECT_GT(stats.perturbation_orders, 1u) << name;
  EXPECT_GT(stats.perturbation_order, 0u) << name;
  EXPECT_EQ(tri.perturbation_rank, perturbation_rank(plc, static_cast<int>(stats.perturbation_order))) << name;
  const ValidationReport report = validate(tri, plc);
  EXPECT_TRUE(report.ok()) << name << "\n" << report.summary();
  tri.perturbation_rank.clear();  // the same simplices, perturbed by vertex id
  const ValidationReport by_id = validate(tri, plc);
  EXPECT_GT(by_id.count("locally-delaunay"), 0u) << name;
  EXPECT_EQ(by_id.counts.size(), 1u) << name << ": only the perturbation's decisions may differ\n" << by_id.summary();
  return {fixtures::simplex_set(tri), stats.perturbation_order};
}

// The three algorithms find the same CDT under the same order.
template <int D>
void expect_agreement_in_a_later_order(const Plc<D>& plc, const std::string& what, const std::vector<Algorithm>& algorithms) {
  std::optional<Retried> first;
  for (const Algorithm algorithm : algorithms) {
    const Retried r = expect_cdt_in_a_later_order(plc, algorithm, what);
    if (!first) {
      first = r;
      continue;
    }
    EXPECT_EQ(r.order, first->order) << what << ", " << to_string(algorithm);
    EXPECT_EQ(r.simplices, first->simplices) << what << ", " << to_string(algorithm);
  }
}

// Grid boxes: every unit square split along (1, 1). The lexicographic order (number 2) pulls each
// square's least corner, on that diagonal; the vertex ids do not.
TEST(PerturbationOrder, GridBoxesGetACdtAsGiven) {
  for (int k : {1, 2, 3}) {
    const std::vector<Algorithm> all(std::begin(kAlgorithms), std::end(kAlgorithms));
    expect_agreement_in_a_later_order(fixtures::grid_box_surface(k), "grid box " + std::to_string(k), all);
  }
}

// The Kuhn-triangulated D-cube with its ids scrambled so that id 0 is not on the Kuhn diagonal.
TEST(PerturbationOrder, KuhnCubesInThreeToFiveDimensions) {
  const std::vector<Algorithm> all(std::begin(kAlgorithms), std::end(kAlgorithms));
  for (uint32_t scramble : {1u, 6u}) {
    expect_agreement_in_a_later_order(fixtures::kuhn_cube_surface<3>(scramble), "3-cube, scramble " + std::to_string(scramble), all);
    expect_agreement_in_a_later_order(fixtures::kuhn_cube_surface<4>(scramble), "4-cube, scramble " + std::to_string(scramble), all);
  }
  // 32 cospherical points make every test a tie: seconds per run, so one algorithm.
  expect_agreement_in_a_later_order(fixtures::kuhn_cube_surface<5>(1), "5-cube", {Algorithm::SweepPlane});
}

// Every algorithm finds the CDT of `plc` in one run, under the vertex-id order.
template <int D>
void expect_one_run(const Plc<D>& plc, const std::string& name) {
  for (const Algorithm algorithm : kAlgorithms) {
    Options options;
    options.algorithm = algorithm;
    CdtStatistics stats;
    options.statistics = &stats;
    const Triangulation<D> tri = cdt(plc, options);
    EXPECT_TRUE(validate(tri, plc).ok()) << name << " " << to_string(algorithm);
    EXPECT_EQ(stats.perturbation_orders, 1u) << name << " " << to_string(algorithm);
    EXPECT_EQ(stats.perturbation_order, 0u) << name << " " << to_string(algorithm);
    EXPECT_TRUE(tri.perturbation_rank.empty()) << name << " " << to_string(algorithm);
  }
}

// Without a scramble the vertex ids pull the origin first: one run, as before.
TEST(PerturbationOrder, OneRunWhenTheIdsWork) { expect_one_run(fixtures::kuhn_cube_surface<4>(0), "4-cube"); }

// Dimension 2: the perturbed points always have a CDT, so no second order is ever tried.
TEST(PerturbationOrder, TwoDimensionsNeedOneOrder) { expect_one_run(fixtures::kuhn_cube_surface<2>(1), "scrambled square"); }

// Right prisms over a triangle (issue item): the staircase split has six cospherical points and a
// tetrahedralization; twisted against Schönhardt's sense its diagonals are convex edges.
TEST(PerturbationOrder, PrismsThatHaveACdt) {
  for (const auto& [name, prism] : {std::pair{std::string("staircase prism"), fixtures::staircase_prism()},
                                    std::pair{std::string("prism twisted the other way"), fixtures::twisted_prism(-0.5)}}) {
    std::optional<std::set<std::vector<uint32_t>>> first;
    for (const Algorithm algorithm : kAlgorithms) {
      Options options;
      options.algorithm = algorithm;
      Triangulation<3> tri;
      try {
        tri = cdt(prism, options);
      } catch (const std::exception& e) {
        ADD_FAILURE() << name << ", " << to_string(algorithm) << ": " << e.what();
        continue;
      }
      EXPECT_TRUE(validate(tri, prism).ok()) << name << ", " << to_string(algorithm);
      EXPECT_EQ(tri.num_points(), 6u) << name;
      EXPECT_GE(tri.num_simplices(), 3u) << name;  // 3 for the staircase, 4 for the convex twisted prism
      if (!first) first = fixtures::simplex_set(tri);
      else EXPECT_EQ(fixtures::simplex_set(tri), *first) << name << ", " << to_string(algorithm);
    }
  }
}

// The staircase prism renumbered so that id 0 is top 4, on one diagonal only: pulled first, it
// leaves the quad (1, 2, 5, 4) split the wrong way; bottom 0, on two, comes first in a later order.
TEST(PerturbationOrder, StaircasePrismRenumbered) {
  Plc<3> prism = fixtures::staircase_prism();
  for (int k = 0; k < 3; ++k) std::swap(prism.points[k], prism.points[3 * 4 + k]);
  for (uint32_t& v : prism.simplices) v = v == 0 ? 4 : v == 4 ? 0 : v;
  ASSERT_TRUE(find_problems(prism).empty());
  const std::vector<Algorithm> all(std::begin(kAlgorithms), std::end(kAlgorithms));
  expect_agreement_in_a_later_order(prism, "staircase prism, ids 0 and 4 exchanged", all);
}

// Schönhardt's twisted prism has no tetrahedralization and no exact tie: one run decides it.
TEST(PerturbationOrder, SchonhardtIsDecidedInOneRun) {
  for (const Algorithm algorithm : kAlgorithms) {
    Options options;
    options.algorithm = algorithm;
    CdtStatistics stats;
    options.statistics = &stats;
    EXPECT_THROW(cdt(fixtures::twisted_prism(0.5), options), NoCdtError) << to_string(algorithm);
    EXPECT_EQ(stats.perturbation_orders, 1u) << to_string(algorithm);
  }
}

// Cospherical but without any tetrahedralization: the untwisted prism split cyclically, and the cube
// of the glTF sample Box.gltf (its six face diagonals are those of none of the 74 triangulations of
// the cube — enumerated). Every order is tried in vain; the error says so and keeps the first
// run's witness.
TEST(PerturbationOrder, NoOrderHelpsWithoutATetrahedralization) {
  Plc<3> box;
  box.points = {-1, -1, 1, 1, -1, 1, -1, 1, 1, 1, 1, 1, 1, -1, -1, -1, -1, -1, 1, 1, -1, -1, 1, -1};
  box.simplices = {0, 1, 2, 3, 2, 1, 1, 0, 4, 5, 4, 0, 3, 1, 6, 4, 6, 1, 2, 3, 7, 6, 7, 3, 0, 2, 5, 7, 5, 2, 5, 7, 4, 6, 4, 7};
  box.exterior.assign(12, ExteriorSide::Negative);
  for (const auto& [name, plc] : {std::pair{std::string("untwisted cyclic prism"), fixtures::twisted_prism(0.0)},
                                  std::pair{std::string("Box.gltf's cube"), box}}) {
    ASSERT_TRUE(find_problems(plc).empty()) << name;
    for (const Algorithm algorithm : kAlgorithms) {
      Options options;
      options.algorithm = algorithm;
      CdtStatistics stats;
      options.statistics = &stats;
      try {
        cdt(plc, options);
        ADD_FAILURE() << name << ", " << to_string(algorithm) << ": a CDT was returned";
      } catch (const NoCdtError& e) {
        // Every run meets cospherical ties, so every distinct order is tried.
        std::set<std::vector<uint32_t>> distinct;
        for (int order = 0; order < kPerturbationOrders; ++order) distinct.insert(perturbation_rank(plc, order));
        EXPECT_EQ(stats.perturbation_orders, distinct.size()) << name << ", " << to_string(algorithm);
        EXPECT_NE(std::string(e.what()).find(std::to_string(stats.perturbation_orders) + " perturbation orders tried"), std::string::npos)
            << e.what();
        EXPECT_FALSE(e.witness().empty()) << name;
      }
    }
  }
}

// Progress reports and cancellation reach into the later orders' runs.
TEST(PerturbationOrder, ProgressAndCancellationAcrossOrders) {
  const Plc<3> box = fixtures::grid_box_surface(6);
  Options options;
  options.algorithm = Algorithm::GiftWrap;  // reports every 1024 faces: the first run fails before that
  std::vector<std::string> phases;
  options.progress = [&](const Progress& p) {
    phases.emplace_back(p.phase);
    return phases.back().find("perturbation order") == std::string::npos;  // cancel in a later order
  };
  EXPECT_THROW(cdt(box, options), CancelledError);
  ASSERT_FALSE(phases.empty());
  EXPECT_EQ(phases.back().rfind("gift-wrapping (perturbation order ", 0), 0u) << phases.back();
}

}  // namespace
