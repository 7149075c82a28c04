// Every algorithm (gift-wrapping, sweep sphere, sweep plane) equals CGAL where the answer is unique
// (random points in general position): Constrained_Delaunay_triangulation_2 for PSLGs and polygons
// with holes, Delaunay_triangulation_3. So does the brute-force CDT oracle in 2D, which the 3D-5D
// tests (brute_force_cdt_test.cpp) trust.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <list>
#include <random>
#include <set>

#include "brute_force_cdt.h"
#include "sweepcdt/cdt.h"

using namespace sweepcdt;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
using Fb2 = CGAL::Constrained_triangulation_face_base_2<K>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb2, Fb2>,
                                                       CGAL::No_constraint_intersection_tag>;
using Triangle = std::set<uint32_t>;

namespace {

// Every algorithm: sweepcdt::kAlgorithms (the cavity sweep, the two sweeps, gift-wrapping).

template <int D>
Triangulation<D> run(const Plc<D>& plc, Algorithm algorithm) {
  Options options;
  options.algorithm = algorithm;
  return cdt(plc, options);
}

template <int D>
std::set<std::set<uint32_t>> simplex_set(const Triangulation<D>& tri) {
  std::set<std::set<uint32_t>> set;
  for (std::size_t t = 0; t < tri.num_simplices(); ++t) set.insert({tri.simplex(t), tri.simplex(t) + D + 1});
  return set;
}

Cdt cgal_cdt(const Plc<2>& plc) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (uint32_t i = 0; i < plc.num_points(); ++i) {
    handles.push_back(cdt.insert(K::Point_2(plc.point(i)[0], plc.point(i)[1])));
    handles.back()->info() = i;
  }
  for (std::size_t j = 0; j < plc.num_simplices(); ++j) cdt.insert_constraint(handles[plc.simplex(j)[0]], handles[plc.simplex(j)[1]]);
  return cdt;
}

// CGAL's faces inside the domain: odd nesting depth counted in constraints crossed from outside.
std::set<Triangle> cgal_domain_faces(const Cdt& cdt) {
  std::map<Cdt::Face_handle, int> depth;
  std::list<std::pair<Cdt::Face_handle, int>> queue{{cdt.infinite_face(), 0}};
  std::list<std::pair<Cdt::Face_handle, int>> next_level;
  while (!queue.empty()) {
    while (!queue.empty()) {
      auto [face, d] = queue.front();
      queue.pop_front();
      if (depth.count(face)) continue;
      depth[face] = d;
      for (int i = 0; i < 3; ++i) {
        const auto n = face->neighbor(i);
        if (depth.count(n)) continue;
        if (cdt.is_constrained({face, i})) next_level.push_back({n, d + 1});
        else queue.push_back({n, d});
      }
    }
    queue.swap(next_level);
  }
  std::set<Triangle> faces;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (depth[f] % 2 == 1) faces.insert({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return faces;
}

std::set<Triangle> cgal_all_faces(const Cdt& cdt) {
  std::set<Triangle> faces;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    faces.insert({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return faces;
}

TEST(AlgorithmsEqualCgal, RandomPslgsEqualCgalCdt2) {
  for (int seed = 0; seed < 200; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Plc<2> plc;
    for (int i = 0; i < 2 * 40; ++i) plc.points.push_back(u(rng));
    std::uniform_int_distribution<uint32_t> pick(0, 39);
    for (int tries = 0; tries < 60 && plc.num_simplices() < 12; ++tries) {
      const uint32_t a = pick(rng), b = pick(rng);
      if (a == b) continue;
      plc.simplices.insert(plc.simplices.end(), {a, b});
      if (!find_problems(plc).empty()) plc.simplices.resize(plc.simplices.size() - 2);
    }
    const auto expected = cgal_all_faces(cgal_cdt(plc));
    for (Algorithm a : kAlgorithms) EXPECT_EQ(simplex_set(run(plc, a)), expected) << to_string(a) << " seed " << seed;
  }
}

// The oracle checks paper §1's definition by brute force; CGAL builds the CDT by incremental insertion
// and flips: nothing shared. Few points (the oracle is O(n^4)), long segments, so occlusion matters.
TEST(AlgorithmsEqualCgal, BruteForceCdtOracleEqualsCgalCdt2) {
  uint64_t accepted_by_occlusion = 0;
  for (int seed = 0; seed < 20; ++seed) {
    std::mt19937_64 rng(500 + seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Plc<2> plc;
    for (int i = 0; i < 2 * 12; ++i) plc.points.push_back(u(rng));
    std::uniform_int_distribution<uint32_t> pick(0, 11);
    for (int tries = 0; tries < 40 && plc.num_simplices() < 4; ++tries) {
      const uint32_t a = pick(rng), b = pick(rng);
      if (a == b) continue;
      plc.simplices.insert(plc.simplices.end(), {a, b});
      if (!find_problems(plc).empty()) plc.simplices.resize(plc.simplices.size() - 2);
    }
    const auto reference = fixtures::brute_force_cdt<2>(plc);
    std::set<Triangle> oracle;
    for (const auto& s : reference.simplices) oracle.insert(Triangle(s.begin(), s.end()));
    EXPECT_EQ(oracle, cgal_all_faces(cgal_cdt(plc))) << "seed " << seed;
    accepted_by_occlusion += reference.counts.accepted_by_occlusion;
  }
  EXPECT_GE(accepted_by_occlusion, 20u) << "occlusion rarely mattered: the comparison checks little";
}

// A star-shaped outer polygon (counterclockwise), a star-shaped hole (clockwise) around the same
// centre, and random points anywhere: only those in the domain belong to the CDT.
TEST(AlgorithmsEqualCgal, PolygonsWithHolesEqualCgalCdt2) {
  const double pi = 3.14159265358979323846;
  int compared = 0;
  for (int seed = 0; seed < 100; ++seed) {
    std::mt19937_64 rng(1000 + seed);
    std::uniform_real_distribution<double> u(0, 1);
    Plc<2> plc;
    auto ring = [&](int n, double r0, double r1, bool clockwise) {
      const uint32_t base = static_cast<uint32_t>(plc.num_points());
      for (int i = 0; i < n; ++i) {
        const double a = 2 * pi * (clockwise ? n - i : i) / n, r = r0 + (r1 - r0) * u(rng);
        plc.points.insert(plc.points.end(), {r * std::cos(a), r * std::sin(a)});
      }
      for (int i = 0; i < n; ++i) plc.simplices.insert(plc.simplices.end(), {base + i, base + (i + 1) % n});
    };
    ring(12, 0.8, 1.0, false);
    ring(7, 0.15, 0.3, true);
    for (int i = 0; i < 25; ++i) plc.points.insert(plc.points.end(), {2.2 * u(rng) - 1.1, 2.2 * u(rng) - 1.1});
    plc.exterior.assign(plc.num_simplices(), ExteriorSide::Negative);  // domain on the left
    if (!find_problems(plc).empty()) continue;  // a random point landed on a segment
    const auto expected = cgal_domain_faces(cgal_cdt(plc));
    for (Algorithm a : kAlgorithms) EXPECT_EQ(simplex_set(run(plc, a)), expected) << to_string(a) << " seed " << seed;
    ++compared;
  }
  EXPECT_GE(compared, 90) << "too many random polygons were invalid: the comparison covers little";
}

TEST(AlgorithmsEqualCgal, RandomPointsEqualCgalDelaunay3) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K>;
  using Dt = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb>>;
  for (int seed = 0; seed < 5; ++seed) {
    std::mt19937_64 rng(77 + seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Plc<3> plc;
    for (int i = 0; i < 3 * 300; ++i) plc.points.push_back(u(rng));
    Dt dt;
    for (uint32_t i = 0; i < 300; ++i) dt.insert(K::Point_3(plc.point(i)[0], plc.point(i)[1], plc.point(i)[2]))->info() = i;
    std::set<std::set<uint32_t>> expected;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      expected.insert({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    for (Algorithm a : kAlgorithms) EXPECT_EQ(simplex_set(run(plc, a)), expected) << to_string(a) << " seed " << seed;
  }
}

}  // namespace
