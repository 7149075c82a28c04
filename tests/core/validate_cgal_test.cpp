// validate() against CGAL's Delaunay and constrained Delaunay triangulations (exact predicates),
// which are unique for random points in general position — and a flip away from them must fail.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "sweepcdt/plc.h"
#include "sweepcdt/predicates/occlusion.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/validate.h"

using namespace sweepcdt;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

namespace {

template <int D>
std::vector<double> random_points(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> p(D * count);
  for (auto& x : p) x = u(rng);
  return p;
}

// Appends simplex ids, positively oriented by sweepcdt's convention.
template <int D>
void add_simplex(Triangulation<D>& tri, std::array<uint32_t, D + 1> ids) {
  predicates::Coords<D + 1> c;
  for (int i = 0; i <= D; ++i) c[i] = tri.point(ids[i]);
  if (predicates::orient<D>(c) == predicates::Sign::Negative) std::swap(ids[0], ids[1]);
  tri.simplices.insert(tri.simplices.end(), ids.begin(), ids.end());
}

template <class Cgal>
Triangulation<2> from_cgal_2d(const Cgal& cgal, const std::vector<double>& points) {
  Triangulation<2> tri;
  tri.points = points;
  tri.num_input_points = static_cast<uint32_t>(points.size() / 2);
  for (auto f = cgal.finite_faces_begin(); f != cgal.finite_faces_end(); ++f)
    add_simplex<2>(tri, {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  compute_neighbors(tri);
  return tri;
}

TEST(ValidateCgal, Delaunay2D) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
  using Dt = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
  for (int seed = 0; seed < 10; ++seed) {
    std::mt19937_64 rng(seed);
    const auto points = random_points<2>(rng, 300);
    Dt dt;
    for (uint32_t i = 0; i < points.size() / 2; ++i) dt.insert(K::Point_2(points[2 * i], points[2 * i + 1]))->info() = i;
    auto tri = from_cgal_2d(dt, points);
    Plc<2> plc;
    plc.points = points;
    const auto report = validate(tri, plc);
    EXPECT_TRUE(report.ok()) << report.summary();

    // Flip one edge of a convex quadrilateral: still a triangulation, no longer Delaunay.
    for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
      const uint32_t nb = tri.neighbors[3 * t];
      if (nb == kNone) continue;
      const uint32_t u = nb / 3, j = nb % 3;
      const uint32_t* s = tri.simplex(t);
      const uint32_t a = s[0], b = s[1], c = s[2], d = tri.simplex(u)[j];
      // Edge bc is shared; the quad a-b-d-c is convex iff segment ad crosses bc.
      if (!predicates::occludes<2>({tri.point(b), tri.point(c)}, tri.point(a), tri.point(d))) continue;
      auto flipped = tri;
      flipped.simplices.clear();
      for (std::size_t k = 0; k < tri.num_simplices(); ++k)
        if (k != t && k != u) flipped.simplices.insert(flipped.simplices.end(), tri.simplex(k), tri.simplex(k) + 3);
      add_simplex<2>(flipped, {a, b, d});
      add_simplex<2>(flipped, {a, d, c});
      compute_neighbors(flipped);
      const auto r = validate(flipped, plc);
      EXPECT_EQ(r.count("locally-delaunay"), 1u) << r.summary();
      EXPECT_EQ(r.counts.size(), 1u) << r.summary();
      break;
    }
  }
}

TEST(ValidateCgal, ConstrainedDelaunay2D) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;
  int non_delaunay_constraints = 0;
  for (int seed = 0; seed < 20; ++seed) {
    std::mt19937_64 rng(100 + seed);
    const auto points = random_points<2>(rng, 120);
    Plc<2> plc;
    plc.points = points;
    // Random long segments, kept only while the PLC stays valid (exactly checked).
    std::uniform_int_distribution<uint32_t> pick(0, 119);
    for (int tries = 0; tries < 200 && plc.num_simplices() < 25; ++tries) {
      const uint32_t a = pick(rng), b = pick(rng);
      if (a == b) continue;
      plc.simplices.insert(plc.simplices.end(), {a, b});
      if (!find_problems(plc).empty()) plc.simplices.resize(plc.simplices.size() - 2);
    }
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> handles;
    for (uint32_t i = 0; i < 120; ++i) {
      handles.push_back(cdt.insert(K::Point_2(points[2 * i], points[2 * i + 1])));
      handles.back()->info() = i;
    }
    for (std::size_t j = 0; j < plc.num_simplices(); ++j) cdt.insert_constraint(handles[plc.simplex(j)[0]], handles[plc.simplex(j)[1]]);
    const auto tri = from_cgal_2d(cdt, points);
    const auto report = validate(tri, plc);
    EXPECT_TRUE(report.ok()) << "seed " << seed << "\n" << report.summary();

    Plc<2> unconstrained;
    unconstrained.points = points;
    non_delaunay_constraints += validate(tri, unconstrained).count("locally-delaunay");
  }
  EXPECT_GT(non_delaunay_constraints, 0) << "the constraints never mattered: the test proves little";
}

TEST(ValidateCgal, Delaunay3D) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K>;
  using Dt = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb>>;
  for (int seed = 0; seed < 5; ++seed) {
    std::mt19937_64 rng(50 + seed);
    const auto points = random_points<3>(rng, 500);
    Dt dt;
    for (uint32_t i = 0; i < points.size() / 3; ++i)
      dt.insert(K::Point_3(points[3 * i], points[3 * i + 1], points[3 * i + 2]))->info() = i;
    Triangulation<3> tri;
    tri.points = points;
    tri.num_input_points = 500;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      add_simplex<3>(tri, {c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
    compute_neighbors(tri);
    Plc<3> plc;
    plc.points = points;
    const auto report = validate(tri, plc);
    EXPECT_TRUE(report.ok()) << report.summary();

    // A 2-3 flip of an interior facet whose two tetrahedra form a convex union.
    bool flipped_one = false;
    for (std::size_t t = 0; t < tri.num_simplices() && !flipped_one; ++t)
      for (int i = 0; i < 4 && !flipped_one; ++i) {
        const uint32_t nb = tri.neighbors[4 * t + i];
        if (nb == kNone) continue;
        const uint32_t* s = tri.simplex(t);
        std::array<uint32_t, 3> f;
        for (int k = 0, j = 0; k < 4; ++k)
          if (k != i) f[j++] = s[k];
        const uint32_t d = s[i], e = tri.simplex(nb / 4)[nb % 4];
        bool convex = true;
        for (int k = 0; k < 3 && convex; ++k)  // the three new tetrahedra must not be flat
          convex = predicates::orient<3>({tri.point(d), tri.point(e), tri.point(f[k]), tri.point(f[(k + 1) % 3])}) != predicates::Sign::Zero;
        if (!convex || !predicates::occludes<3>({tri.point(f[0]), tri.point(f[1]), tri.point(f[2])}, tri.point(d), tri.point(e))) continue;
        Triangulation<3> flipped = tri;
        flipped.simplices.clear();
        for (std::size_t k = 0; k < tri.num_simplices(); ++k)
          if (k != t && k != nb / 4) flipped.simplices.insert(flipped.simplices.end(), tri.simplex(k), tri.simplex(k) + 4);
        for (int k = 0; k < 3; ++k) add_simplex<3>(flipped, {d, e, f[k], f[(k + 1) % 3]});
        compute_neighbors(flipped);
        const auto r = validate(flipped, plc);
        EXPECT_GE(r.count("locally-delaunay"), 1u) << r.summary();
        EXPECT_EQ(r.counts.size(), 1u) << r.summary();
        flipped_one = true;
      }
    EXPECT_TRUE(flipped_one);
  }
}

}  // namespace
