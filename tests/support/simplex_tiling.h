// Is a set of D-simplices a triangulation of a convex-hull PLC? Decided exactly, for the brute-force
// CDT oracle (tests only):
//   * no two simplices have intersecting interiors (exact LP where no facet hyperplane separates them),
//   * their volumes (exact rationals) add up to the hull's, taken from the brute-force Delaunay
//     triangulation, so together they cover the hull,
//   * they meet facet to facet: each facet is shared by two simplices or lies on the hull boundary, and
//   * every constraining simplex is a facet (a PLC has no vertex on a constraint but its own, so a
//     constraint that is a union of facets is one facet).
// With disjoint interiors these are what a triangulation of the PLC needs. The last one is not implied
// by the others even when no simplex's interior meets a constraint: a facet lying in aff(t) may cross
// t (paper §1 asks every simplex of a CDT, of any dimension, to be a constraint's face or constrained
// Delaunay; the D-simplices alone do not see this). Disjointness matters on its own: every CDT of a
// PLC is a subset of its constrained Delaunay simplices, and a subset of a disjoint set covers the
// hull only if it is the whole set. So when the constrained Delaunay simplices have disjoint interiors,
// the PLC has a CDT iff they are a triangulation of it.
#pragma once
#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <vector>

#include "brute_force_delaunay.h"
#include "rational_affine.h"
#include "rational_lp.h"
#include "sweepcdt/plc.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::fixtures {

struct TilingReport {
  bool interiors_disjoint = true;
  bool covers_hull = false;      // total volume equals the hull's (meaningful with disjoint interiors)
  bool facet_to_facet = true;
  bool constraints_are_facets = true;
  uint64_t overlapping_pairs = 0;
  bool triangulation() const { return interiors_disjoint && covers_hull && facet_to_facet && constraints_are_facets; }
};

namespace tiling_detail {

template <int D>
std::vector<ref::Vec> rational(const std::vector<double>& points, const std::vector<uint32_t>& ids) {
  std::vector<ref::Vec> q;
  for (uint32_t i : ids) q.push_back(ref::point(points.data() + std::size_t{i} * D, D));
  return q;
}

// D! times the volume.
template <int D>
ref::Q scaled_volume(const std::vector<double>& points, const std::vector<uint32_t>& ids) {
  const auto q = rational<D>(points, ids);
  ref::Mat m;
  for (int i = 1; i <= D; ++i) m.push_back(ref::sub(q[i], q[0]));
  return abs(ref::det(m));
}

// Do the interiors of two non-degenerate D-simplices meet?
template <int D>
bool interiors_overlap(const std::vector<double>& points, const std::vector<uint32_t>& a,
                       const std::vector<uint32_t>& b) {
  auto pt = [&](uint32_t i) { return points.data() + std::size_t{i} * D; };
  // Fast exact exit: a facet hyperplane of one simplex with the other on its closed outer side.
  for (const auto* pair : {&a, &b}) {
    const auto& s = *pair;
    const auto& other = pair == &a ? b : a;
    predicates::Coords<D + 1> c;
    for (int i = 0; i <= D; ++i) c[i] = pt(s[i]);
    const auto o = predicates::orient<D>(c);
    for (int i = 0; i <= D; ++i) {
      bool separated = true;
      for (int j = 0; j <= D && separated; ++j) {
        auto ci = c;
        ci[i] = pt(other[j]);
        separated = predicates::to_int(predicates::orient<D>(ci) * o) <= 0;
      }
      if (separated) return false;
    }
  }
  // p = sum_i beta_i a_i with beta > 0 (interior of a), and every facet function of b positive at p.
  const auto qa = rational<D>(points, a), qb = rational<D>(points, b);
  std::vector<lp::Row> strict(D + 1, lp::Row(D + 1));
  for (int i = 0; i <= D; ++i) strict[i][i] = 1;
  for (int k = 0; k <= D; ++k) {
    const Affine f = facet_function(qb, k);
    lp::Row row(D + 1);
    for (int i = 0; i <= D; ++i) row[i] = f.at(qa[i]);
    strict.push_back(row);
  }
  return lp::strictly_feasible(strict, {}, D + 1);
}

// Do all points lie on one closed side of the hyperplane through `facet`?
template <int D>
bool on_hull_boundary(const std::vector<double>& points, const std::vector<uint32_t>& facet) {
  predicates::Coords<D + 1> c;
  for (int i = 0; i < D; ++i) c[i] = points.data() + std::size_t{facet[i]} * D;
  bool positive = false, negative = false;
  for (std::size_t p = 0; p < points.size() / D; ++p) {
    c[D] = points.data() + p * D;
    const auto o = predicates::orient<D>(c);
    positive |= o == predicates::Sign::Positive;
    negative |= o == predicates::Sign::Negative;
  }
  return !(positive && negative);
}

}  // namespace tiling_detail

template <int D>
TilingReport tiling_report(const Plc<D>& plc, const std::set<std::vector<uint32_t>>& simplices) {
  const std::vector<double>& points = plc.points;
  TilingReport report;
  const std::vector<std::vector<uint32_t>> list(simplices.begin(), simplices.end());
  for (std::size_t i = 0; i < list.size(); ++i)
    for (std::size_t j = i + 1; j < list.size(); ++j)
      if (tiling_detail::interiors_overlap<D>(points, list[i], list[j])) ++report.overlapping_pairs;
  report.interiors_disjoint = report.overlapping_pairs == 0;

  ref::Q volume = 0, hull = 0;
  for (const auto& s : list) volume += tiling_detail::scaled_volume<D>(points, s);
  const auto delaunay = brute_force_delaunay<D>(points);
  for (std::size_t t = 0; t < delaunay.num_simplices(); ++t)
    hull += tiling_detail::scaled_volume<D>(points, {delaunay.simplex(t), delaunay.simplex(t) + D + 1});
  report.covers_hull = sgn(hull) > 0 && volume == hull;

  std::map<std::vector<uint32_t>, int> facets;
  for (const auto& s : list)
    for (int i = 0; i <= D; ++i) {
      std::vector<uint32_t> f = s;
      f.erase(f.begin() + i);
      ++facets[f];
    }
  for (const auto& [f, count] : facets)
    if (count > 2 || (count == 1 && !tiling_detail::on_hull_boundary<D>(points, f))) report.facet_to_facet = false;
  for (std::size_t j = 0; j < plc.num_simplices(); ++j) {
    std::vector<uint32_t> t(plc.simplex(j), plc.simplex(j) + D);
    std::sort(t.begin(), t.end());
    if (!facets.count(t)) report.constraints_are_facets = false;
  }
  return report;
}

}  // namespace sweepcdt::fixtures
