// The brute-force CDT oracle (tests/support/brute_force_cdt.h), which checks the definition of paper §1
// directly with exact arithmetic, first on hand-made PLCs whose answer is known, then against every
// algorithm on small random constrained PLCs in D = 2..5 with grid degeneracies: a returned CDT must be
// exactly the set of constrained Delaunay simplices, and NoCdtError must come with a set of
// constrained Delaunay simplices that is not a triangulation.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <numeric>
#include <random>
#include <set>
#include <map>
#include <sstream>

#include "brute_force_cdt.h"
#include "random_plc.h"
#include "brute_force_delaunay.h"
#include "simplex_tiling.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/perturbation_order.h"
#include "sweepcdt/predicates/occlusion.h"
#include "triangulation_util.h"

using namespace sweepcdt;
using fixtures::Sight;
using Set = std::set<std::vector<uint32_t>>;

namespace {

// Every algorithm: sweepcdt::kAlgorithms (the cavity sweep, the two sweeps, gift-wrapping).

// The PLC with full precision, so a failure can be replayed.
template <int D>
std::string describe(const Plc<D>& plc) {
  std::ostringstream out;
  char buffer[32];
  out << "points:";
  for (std::size_t i = 0; i < plc.points.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%.17g", plc.points[i]);
    out << (i % D ? " " : "\n  ") << buffer;
  }
  out << "\nsimplices:";
  for (std::size_t j = 0; j < plc.simplices.size(); ++j) out << (j % D ? " " : "\n  ") << plc.simplices[j];
  return out.str();
}

template <int D>
Set delaunay_set(const Plc<D>& plc) {
  return fixtures::simplex_set(fixtures::brute_force_delaunay<D>(plc.points));
}

// What comparing PLCs with every algorithm found.
struct Tally {
  int with_cdt = 0, without_cdt = 0;  // PLCs, by the oracle's verdict under the vertex-id order
  int with_cdt_in_another_order = 0;  // no CDT by vertex id, one under a later order cdt() found
  fixtures::BruteForceCdtCounts oracle;
  void add(const fixtures::BruteForceCdtCounts& c) {
    oracle.candidates += c.candidates;
    oracle.crossed += c.crossed;
    oracle.visible += c.visible;
    oracle.accepted_by_occlusion += c.accepted_by_occlusion;
    oracle.hidden += c.hidden;
    oracle.hidden_by_union += c.hidden_by_union;
    oracle.linear_programs += c.linear_programs;
  }
};

// The oracle's verdict under one perturbation order: the constrained Delaunay simplices in the PLC's
// ids, and whether they triangulate it.
struct Verdict {
  Set simplices;
  bool triangulation = false;
};

// The oracle under perturbation order `rank` (paper §6; sweepcdt/perturbation_order.h): vertex v is
// perturbed as if its id were rank[v]. Written here from scratch, not with cdt()'s own renaming: the
// PLC with point v moved to index rank[v], its answer renamed back.
template <int D>
Verdict oracle_in_order(const Plc<D>& plc, const std::vector<uint32_t>& rank, const std::string& label, Tally& tally) {
  Plc<D> renamed = plc;
  std::vector<uint32_t> back(rank.size());
  for (uint32_t v = 0; v < rank.size(); ++v) {
    back[rank[v]] = v;
    std::copy_n(plc.points.begin() + std::size_t{v} * D, D, renamed.points.begin() + std::size_t{rank[v]} * D);
  }
  for (uint32_t& id : renamed.simplices) id = rank[id];
  const auto reference = fixtures::brute_force_cdt<D>(renamed);
  tally.add(reference.counts);
  const auto tiling = fixtures::tiling_report<D>(renamed, reference.simplices);
  EXPECT_TRUE(tiling.interiors_disjoint)
      << tiling.overlapping_pairs << " overlapping pairs: " << label << "\n" << describe(plc);
  Verdict verdict;
  verdict.triangulation = tiling.triangulation();
  for (const auto& simplex : reference.simplices) {
    std::vector<uint32_t> s;
    for (uint32_t id : simplex) s.push_back(back[id]);
    std::sort(s.begin(), s.end());
    verdict.simplices.insert(s);
  }
  return verdict;
}

// Every algorithm against the oracle. The constrained Delaunay simplices must have disjoint
// interiors (paper §6: overlaps come from cospherical vertices, which the perturbation removes); then
// the perturbed PLC has a CDT iff they triangulate it (simplex_tiling.h), and that CDT is unique.
// cdt() perturbs by vertex id first and, when that finds no CDT after exact ties, tries the later
// orders of perturbation_order.h. So a returned CDT must be exactly the oracle's simplices under the
// order it reports, and the id order must have none when it reports another; NoCdtError must come
// with no CDT under any order cdt() may try — which also tests its rule of not retrying after a run
// that met no tie.
template <int D>
void compare_with_algorithms(const Plc<D>& plc, const std::string& label, Tally& tally) {
  std::map<int, Verdict> verdicts;  // by order, computed once for all algorithms
  const auto verdict = [&](int order) -> const Verdict& {
    auto it = verdicts.find(order);
    if (it == verdicts.end())
      it = verdicts.emplace(order, oracle_in_order(plc, perturbation_rank(plc, order), label, tally)).first;
    return it->second;
  };
  const bool has_cdt = verdict(0).triangulation;
  bool found_in_other_order = false;
  for (Algorithm algorithm : kAlgorithms) {
    Options options;
    options.algorithm = algorithm;
    CdtStatistics stats;
    options.statistics = &stats;
    const std::string where = label + " " + to_string(algorithm) + "\n" + describe(plc);
    try {
      const auto tri = cdt(plc, options);
      const int order = static_cast<int>(stats.perturbation_order);
      EXPECT_EQ(tri.perturbation_rank.empty(), order == 0) << where;
      if (order != 0) {
        EXPECT_EQ(tri.perturbation_rank, perturbation_rank(plc, order)) << where;
        EXPECT_FALSE(has_cdt) << "order " << order << " used, but the vertex-id order has a CDT: " << where;
        found_in_other_order = true;
      }
      EXPECT_TRUE(verdict(order).triangulation) << "a CDT was returned, but the constrained Delaunay simplices "
                                                   "of perturbation order " << order << " do not triangulate the PLC: " << where;
      EXPECT_EQ(fixtures::simplex_set(tri), verdict(order).simplices) << "order " << order << ": " << where;
    } catch (const NoCdtError& e) {
      for (int order = 0; order < kPerturbationOrders; ++order)
        EXPECT_FALSE(verdict(order).triangulation) << "NoCdtError (" << e.what() << "), but the constrained Delaunay "
                                                      "simplices of perturbation order " << order << " are a CDT: " << where;
    }
  }
  ++(has_cdt ? tally.with_cdt : found_in_other_order ? tally.with_cdt_in_another_order : tally.without_cdt);
}

// ---- the exact linear program -------------------------------------------------------------------

TEST(BruteForceCdtOracle, StrictFeasibilityIsExact) {
  using fixtures::lp::Row;
  using fixtures::lp::strictly_feasible;
  const Row x0_above_x1{1, -1}, x1_above_x0{-1, 1}, negative_sum{-1, -1};
  EXPECT_TRUE(strictly_feasible({x0_above_x1}, {}, 2));
  EXPECT_TRUE(strictly_feasible({}, {x0_above_x1, x1_above_x0}, 2));               // x0 = x1 = 1/2
  EXPECT_FALSE(strictly_feasible({x0_above_x1}, {x1_above_x0}, 2));                // only x0 = x1
  EXPECT_FALSE(strictly_feasible({}, {negative_sum}, 2));                          // not on the simplex
  // x0 >= 2 x1 >= 4 x2 >= 8 x0 forces x = 0 off the simplex; dropping one link leaves a point.
  const Row a{1, -2, 0}, b{0, 1, -2}, c{-2, 0, 1};
  EXPECT_FALSE(strictly_feasible({}, {a, b, c}, 3));
  EXPECT_TRUE(strictly_feasible({}, {a, b}, 3));
  // A sliver: x0 > 1000 x1 and x1 > 0 (as x1 - 0 x0 > 0): feasible, but only near the vertex e_0.
  EXPECT_TRUE(strictly_feasible({Row{1, -1000}, Row{0, 1}}, {}, 2));
  EXPECT_FALSE(strictly_feasible({Row{1, -1000}, Row{0, 1}}, {Row{-1, 999}}, 2));
}

// ---- condition (1): constraints meeting the interior --------------------------------------------

TEST(BruteForceCdtOracle, ConstraintsMeetingTheInterior) {
  Plc<2> plc;
  // Triangle 0 1 2; 3 inside it; 4, 5, 6 outside; the line of 4-5 crosses it.
  plc.points = {0, 0, 4, 0, 0, 4, 1, 1, 3, 5, 2.5, 3, -1, 7};
  plc.simplices = {0, 1,  3, 4,  2, 6,  4, 5};
  ASSERT_TRUE(find_problems(plc).empty());
  fixtures::CdtOracle<2> oracle(plc);
  const std::array<uint32_t, 3> s{0, 1, 2};
  EXPECT_FALSE(oracle.meets_interior(s, 0));  // an edge of s
  EXPECT_TRUE(oracle.meets_interior(s, 1));   // from a point inside to one outside
  EXPECT_FALSE(oracle.meets_interior(s, 2));  // touches s at its vertex 2 only
  EXPECT_FALSE(oracle.meets_interior(s, 3));  // outside, though its line crosses s
  EXPECT_TRUE(oracle.meets_interior({0, 1, 4}, 1));  // 3-4 from the interior of 0 1 4 to its vertex
}

// ---- condition (2): the paper's Figure 3, a vertex hidden behind a segment -------------------------

// Triangle 0 1 2 has circumcircle centre (0, -1.5), radius 2.5. Vertex 3 = (0, -3) lies inside it,
// behind the segment 4-5 (y = -2) whose endpoints lie outside it: 0 1 2 is constrained Delaunay but
// not Delaunay.
Plc<2> figure3() {
  Plc<2> plc;
  plc.points = {-2, 0, 2, 0, 0, 1, 0, -3, -4, -2, 4, -2};
  plc.simplices = {4, 5};
  return plc;
}

TEST(BruteForceCdtOracle, Figure3HiddenBehindASegment) {
  const Plc<2> plc = figure3();
  fixtures::CdtOracle<2> oracle(plc);
  EXPECT_EQ(oracle.sight({0, 1, 2}, 3), Sight::HiddenBySingle);
  const auto reference = fixtures::brute_force_cdt<2>(plc);
  EXPECT_TRUE(reference.simplices.count({0, 1, 2}));
  EXPECT_FALSE(delaunay_set(plc).count({0, 1, 2}));
  EXPECT_GE(reference.counts.accepted_by_occlusion, 1u);
  Tally tally;
  compare_with_algorithms(plc, "figure 3", tally);
  EXPECT_EQ(tally.with_cdt, 1);  // every PSLG has a CDT

  Plc<2> open = plc;  // without the segment 3 is visible and the answer is Delaunay's
  open.simplices.clear();
  EXPECT_EQ(fixtures::CdtOracle<2>(open).sight({0, 1, 2}, 3), Sight::Visible);
  EXPECT_EQ(fixtures::brute_force_cdt<2>(open).simplices, delaunay_set(open));
}

// Triangle 0 1 2 has circumcircle centre (0, 0), radius 3, and centroid (0, 1). Vertex 3 = (0, -2) is
// inside; segments on y = -1 lie between.
//   * gap: 4-5 from x = -5 to 1 and 6-7 from 1.25 to 5. 4-5 hides 3 from the centroid, but through the
//     gap 3 is seen from points near vertex 1: only the exact search over int(s) can find them.
//   * union: 4-5 and 5-7 hide 3 from all of int(s) together, neither alone. In 2D their shared
//     endpoint 5 then lies in conv(3, s), inside the circle, and nothing hides 5: 0 1 2 is still not
//     constrained Delaunay. (The 3D and 4D walls below avoid that.)
TEST(BruteForceCdtOracle, GapAndUnionOfTwoSegments) {
  Plc<2> gap;
  gap.points = {-3, 0, 3, 0, 0, 3, 0, -2, -5, -1, 1, -1, 1.25, -1, 5, -1};
  gap.simplices = {4, 5, 6, 7};
  ASSERT_TRUE(find_problems(gap).empty());
  const double centroid[2] = {0, 1};
  EXPECT_TRUE(predicates::occludes<2>({gap.point(4), gap.point(5)}, centroid, gap.point(3)));
  EXPECT_EQ(fixtures::CdtOracle<2>(gap).sight({0, 1, 2}, 3), Sight::Visible);
  EXPECT_FALSE(fixtures::brute_force_cdt<2>(gap).simplices.count({0, 1, 2}));

  Plc<2> joined;  // points 0..5 of gap, then 6 = (5, -1)
  joined.points.assign(gap.points.begin(), gap.points.begin() + 12);
  joined.points.insert(joined.points.end(), {5, -1});
  joined.simplices = {4, 5, 5, 6};
  ASSERT_TRUE(find_problems(joined).empty());
  fixtures::CdtOracle<2> oracle(joined);
  EXPECT_EQ(oracle.sight({0, 1, 2}, 3), Sight::HiddenByUnion);
  EXPECT_EQ(oracle.sight({0, 1, 2}, 5), Sight::Visible);
  EXPECT_FALSE(fixtures::brute_force_cdt<2>(joined).simplices.count({0, 1, 2}));
}

// ---- the union of two constraints that share a ridge, D = 3 and 4 ---------------------------------

// s = 0..D: +-3 e_1, 3 e_2, ..., 3 e_D, on the sphere of radius 3 about the origin, in x_D >= 0.
// Vertex D+1 = -2 e_D is inside that sphere. The wall lies in x_D = -1, far outside the sphere except
// across its middle: two constraining simplices sharing a ridge in x_1 = 0, which splits the shadow of
// s (s has points with x_1 < 0 and > 0). So D+1 is hidden by their union only, and s is constrained
// Delaunay. `ridge` are the shared vertices, `apexes` the others (wall coordinates x_1..x_{D-1}); one
// wall simplex (ridge + apex) per apex.
template <int D>
Plc<D> wall_case(const std::vector<std::array<double, D - 1>>& ridge,
                 const std::vector<std::array<double, D - 1>>& apexes) {
  Plc<D> plc;
  auto add = [&](std::array<double, D> p) { plc.points.insert(plc.points.end(), p.begin(), p.end()); };
  std::array<double, D> p{};
  p[0] = 3, add(p), p[0] = -3, add(p), p[0] = 0;
  for (int k = 1; k < D; ++k) p[k] = 3, add(p), p[k] = 0;
  p[D - 1] = -2, add(p);
  auto on_wall = [&](const std::array<double, D - 1>& w) {
    std::array<double, D> q;
    std::copy(w.begin(), w.end(), q.begin());
    q[D - 1] = -1;
    add(q);
  };
  const uint32_t first = static_cast<uint32_t>(plc.num_points());
  for (const auto& w : ridge) on_wall(w);
  for (const auto& w : apexes) on_wall(w);
  for (uint32_t a = 0; a < apexes.size(); ++a) {
    for (uint32_t j = 0; j < D - 1; ++j) plc.simplices.push_back(first + j);
    plc.simplices.push_back(first + D - 1 + a);
  }
  return plc;
}

template <int D>
void hidden_by_a_wall(const Plc<D>& plc, Sight expected) {
  ASSERT_TRUE(find_problems(plc).empty()) << describe(plc);
  std::array<uint32_t, D + 1> s;
  for (uint32_t i = 0; i <= D; ++i) s[i] = i;
  const std::vector<uint32_t> sorted(s.begin(), s.end());
  fixtures::CdtOracle<D> oracle(plc);
  EXPECT_EQ(oracle.sight(s, D + 1), expected);
  const auto reference = fixtures::brute_force_cdt<D>(plc);
  EXPECT_EQ(reference.simplices.count(sorted) == 1, expected != Sight::Visible);
  EXPECT_FALSE(delaunay_set(plc).count(sorted));
  EXPECT_EQ(reference.counts.hidden_by_union >= 1, expected == Sight::HiddenByUnion);
  Tally tally;
  compare_with_algorithms(plc, "wall", tally);
}

TEST(BruteForceCdtOracle, HiddenByTheUnionOfTwoTriangles3D) {
  // Wall corners (0, +-30), (+-30, 0): a square, its diagonal x = 0 shared.
  hidden_by_a_wall(wall_case<3>({{0, -30}, {0, 30}}, {{30, 0}, {-30, 0}}), Sight::HiddenByUnion);
  // Either triangle alone leaves half of the shadow open.
  hidden_by_a_wall(wall_case<3>({{0, -30}, {0, 30}}, {{30, 0}}), Sight::Visible);
  hidden_by_a_wall(wall_case<3>({{0, -30}, {0, 30}}, {{-30, 0}}), Sight::Visible);
}

TEST(BruteForceCdtOracle, HiddenByTheUnionOfTwoTetrahedra4D) {
  // A bipyramid over the triangle (x_2, x_3) = (-30, -30), (60, -30), (-30, 60) in x_1 = 0.
  const std::vector<std::array<double, 3>> ridge{{0, -30, -30}, {0, 60, -30}, {0, -30, 60}};
  hidden_by_a_wall(wall_case<4>(ridge, {{60, 0, 0}, {-60, 0, 0}}), Sight::HiddenByUnion);
  hidden_by_a_wall(wall_case<4>(ridge, {{60, 0, 0}}), Sight::Visible);
  hidden_by_a_wall(wall_case<4>(ridge, {{-60, 0, 0}}), Sight::Visible);
}

// Two wall triangles with a gap x in (1, 1.25) between them: the centroid (0, 3/4, 3/4) of s is
// hidden, vertex 4 is still seen through the gap from points of int(s) near (2.4, 0.2, 0.2).
TEST(BruteForceCdtOracle, VisibleThroughAGap3D) {
  Plc<3> plc = wall_case<3>({{1, -30}, {1, 30}}, {{-30, 0}});
  plc.points.insert(plc.points.end(), {1.25, -30, -1, 1.25, 30, -1, 32, 0, -1});
  plc.simplices.insert(plc.simplices.end(), {8, 9, 10});
  ASSERT_TRUE(find_problems(plc).empty());
  const double centroid[3] = {0, 0.75, 0.75};
  EXPECT_TRUE(predicates::occludes<3>({plc.point(5), plc.point(6), plc.point(7)}, centroid, plc.point(4)));
  hidden_by_a_wall(plc, Sight::Visible);
}

// ---- random constrained PLCs, every algorithm against the oracle ---------------------------------

// A wall in the hyperplane x_a = 2 (a random axis): the simplex with vertices 0 and (3D - 2) e_i in
// the other coordinates (reflected along random axes), which covers their middle [1, 3]^{D-1}; with
// `split`, cut in two at the midpoint of an edge (two constraints sharing a ridge). The other points
// lie on x_a = 1 or 3 (2D: also 0 or 4) with the other coordinates in {1, 2, 3}, beside the wall:
// simplices with a facet on the wall have circumspheres that reach through it to vertices it hides.
constexpr double kOffWall[] = {1, 3, 0, 4};

template <int D>
Plc<D> random_wall_plc(std::mt19937_64& rng, int count, bool split) {
  std::uniform_int_distribution<int> middle(1, 3), axis(0, D - 1), coin(0, 1), off_wall(0, 3);
  for (;;) {
    Plc<D> plc;
    std::set<std::vector<double>> seen;
    const int a = axis(rng);
    std::vector<int> reflect(D);
    for (auto& r : reflect) r = coin(rng);
    auto add = [&](std::vector<double> p) {
      if (!seen.insert(p).second) return false;
      plc.points.insert(plc.points.end(), p.begin(), p.end());
      return true;
    };
    const double far = 3 * D - 2;
    for (int i = 0; i < D; ++i) {  // wall vertex i: 0, or far along the i-th axis other than a
      std::vector<double> p(D, 0.0);
      if (i > 0) p[(a + i) % D] = far;
      for (int k = 0; k < D; ++k) p[k] = reflect[k] ? 4 - p[k] : p[k];
      p[a] = 2;
      add(p);
    }
    plc.simplices.resize(D);
    std::iota(plc.simplices.begin(), plc.simplices.end(), 0u);
    if (split) {  // midpoint m of edge 0-1: constraints (m, 1, 2..) and (0, m, 2..)
      std::vector<double> m(D);
      for (int k = 0; k < D; ++k) m[k] = (plc.points[k] + plc.points[D + k]) / 2;
      add(m);
      plc.simplices[0] = D;
      for (uint32_t j = 0; j < D; ++j) plc.simplices.push_back(j == 1 ? D : j);
    }
    while (static_cast<int>(plc.num_points()) < count) {
      std::vector<double> p(D);
      for (auto& x : p) x = middle(rng);
      p[a] = kOffWall[off_wall(rng) % (D == 2 ? 4 : 2)];
      add(p);
    }
    if (find_problems(plc).empty()) return plc;
  }
}

// Half the seeds a wall (always a CDT here, and much occlusion, by unions too), half constraints
// drawn among the inner points (often no CDT in D >= 3). Both sides of every comparison must occur,
// and occlusion must have decided some simplices, or the test would check little.
template <int D>
void random_against_oracle(int seeds, int inner, int outer, int constraints) {
  const auto start = std::chrono::steady_clock::now();
  Tally tally;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(4200 * D + seed);
    const Plc<D> plc = seed % 2 ? fixtures::random_constrained_plc<D>(rng, inner, outer, 1 + seed % constraints)
                                : random_wall_plc<D>(rng, inner + outer, (seed / 2) % 2);
    if (plc.num_simplices() == 0) continue;
    compare_with_algorithms(plc, "D=" + std::to_string(D) + " seed " + std::to_string(seed), tally);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto& c = tally.oracle;
  std::printf("[ oracle ] D=%d: %d PLCs with a CDT, %d with one under another perturbation order only, %d without; %llu candidate simplices: %llu crossed, %llu see a "
              "vertex, %llu accepted by occlusion (%llu hidden vertices, %llu by unions only); %llu LPs; %.2f s\n",
              D, tally.with_cdt, tally.with_cdt_in_another_order, tally.without_cdt, (unsigned long long)c.candidates, (unsigned long long)c.crossed,
              (unsigned long long)c.visible, (unsigned long long)c.accepted_by_occlusion, (unsigned long long)c.hidden,
              (unsigned long long)c.hidden_by_union, (unsigned long long)c.linear_programs, seconds);
  EXPECT_GE(tally.with_cdt, 10) << "too few CDTs compared";
  EXPECT_GE(c.accepted_by_occlusion, 10u) << "occlusion rarely mattered: the constraints are hardly tested";
  if (D == 2) {
    EXPECT_EQ(tally.without_cdt, 0) << "every PSLG has a CDT";
  } else {
    EXPECT_GE(tally.without_cdt, 1) << "NoCdtError was never checked";
    EXPECT_GE(c.hidden_by_union, 1u) << "no vertex was hidden by a union of constraints only";
  }
}

TEST(BruteForceCdt, RandomConstrained2D) { random_against_oracle<2>(30, 5, 6, 3); }
TEST(BruteForceCdt, RandomConstrained3D) { random_against_oracle<3>(30, 5, 5, 3); }
TEST(BruteForceCdt, RandomConstrained4D) { random_against_oracle<4>(24, 6, 4, 3); }
TEST(BruteForceCdt, RandomConstrained5D) { random_against_oracle<5>(24, 7, 3, 2); }

}  // namespace
