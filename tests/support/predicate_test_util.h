// Shared helpers of the predicate tests: point storage, random and degenerate generators, conversion
// to the rational reference, replayable printing (%.17g) and a failure budget that keeps a broken
// predicate from flooding the log.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "rational_reference.h"
#include "sweepcdt/predicates.h"

namespace sweepcdt::testutil {

namespace pr = sweepcdt::predicates;

template <int D>
using Point = std::array<double, D>;

using Dim1to5 = ::testing::Types<std::integral_constant<int, 1>, std::integral_constant<int, 2>,
                                 std::integral_constant<int, 3>, std::integral_constant<int, 4>,
                                 std::integral_constant<int, 5>>;
using Dim2to5 = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>,
                                 std::integral_constant<int, 4>, std::integral_constant<int, 5>>;

// gtest names typed-test instances "D2", "D3", ...
struct DimName {
  template <class T>
  static std::string GetName(int) {
    return "D" + std::to_string(T::value);
  }
};

// ---- printing -----------------------------------------------------------------------------------

inline std::string fmt(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

inline std::string fmt_point(const double* x, int dim) {
  std::string s = "(";
  for (int k = 0; k < dim; ++k) s += (k ? ", " : "") + fmt(x[k]);
  return s + ")";
}

template <int D, std::size_t N>
std::string dump(const std::array<const double*, N>& p) {
  std::string s;
  for (std::size_t i = 0; i < N; ++i) s += "  p" + std::to_string(i) + " = " + fmt_point(p[i], D) + "\n";
  return s;
}

template <int D, std::size_t N>
std::string dump(const std::array<pr::Vertex, N>& p) {
  std::string s;
  for (std::size_t i = 0; i < N; ++i)
    s += "  v" + std::to_string(i) + " = " + fmt_point(p[i].x, D) + " id " + std::to_string(p[i].id) + "\n";
  return s;
}

template <int D>
std::string dump_point(const char* name, const double* x) {
  return std::string("  ") + name + " = " + fmt_point(x, D) + "\n";
}

inline const char* sign_name(int s) { return s < 0 ? "Negative" : s > 0 ? "Positive" : "Zero"; }
inline const char* sign_name(pr::Sign s) { return sign_name(pr::to_int(s)); }

// Counts failures; only the first few are reported in full.
struct FailureBudget {
  int failures = 0;
  int limit = 8;
  bool fail() { return ++failures <= limit; }
};

// ---- conversion to the reference ----------------------------------------------------------------

template <int D>
ref::Vec vec(const double* x) {
  return ref::point(x, D);
}

template <int D, std::size_t N>
std::vector<ref::Vec> vecs(const std::array<const double*, N>& p) {
  std::vector<ref::Vec> v;
  for (const double* x : p) v.push_back(ref::point(x, D));
  return v;
}

template <int D, std::size_t N>
std::vector<ref::Vec> vecs(const std::array<pr::Vertex, N>& p) {
  std::vector<ref::Vec> v;
  for (const auto& x : p) v.push_back(ref::point(x.x, D));
  return v;
}

template <std::size_t N>
std::vector<uint32_t> ids_of(const std::array<pr::Vertex, N>& p) {
  std::vector<uint32_t> ids;
  for (const auto& x : p) ids.push_back(x.id);
  return ids;
}

// ---- random generation --------------------------------------------------------------------------

using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double lo = -1.0, double hi = 1.0) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

inline int uniform_int(Rng& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

// Moves x by `ulps` units in the last place (towards +inf if positive).
inline double nudge(double x, int ulps) {
  for (; ulps > 0; --ulps) x = std::nextafter(x, INFINITY);
  for (; ulps < 0; ++ulps) x = std::nextafter(x, -INFINITY);
  return x;
}

template <int D>
Point<D> random_point(Rng& rng, double lo = -1.0, double hi = 1.0) {
  Point<D> p;
  for (double& x : p) x = uniform(rng, lo, hi);
  return p;
}

template <int D>
Point<D> grid_point(Rng& rng, int lo, int hi) {
  Point<D> p;
  for (double& x : p) x = uniform_int(rng, lo, hi);
  return p;
}

// An integer hyperplane  sum_k n_k x_k = c  whose normal has n_k = 0 for k < lead and n_lead = +-1,
// so it is parallel to the first `lead` axes; point() gives integer points on it.
template <int D>
struct GridHyperplane {
  std::array<int, D> n{};
  int c = 0;
  int lead = 0;

  static GridHyperplane random(Rng& rng, int lead) {
    GridHyperplane h;
    h.lead = lead;
    for (int k = lead; k < D; ++k) h.n[k] = uniform_int(rng, -1, 1);
    h.n[lead] = uniform_int(rng, 0, 1) ? 1 : -1;
    h.c = uniform_int(rng, -2, 2);
    return h;
  }
  Point<D> point(Rng& rng, int lo, int hi) const {
    Point<D> p = grid_point<D>(rng, lo, hi);
    int rest = c;
    for (int k = 0; k < D; ++k)
      if (k != lead) rest -= n[k] * static_cast<int>(p[k]);
    p[lead] = rest * n[lead];  // n_lead = +-1
    return p;
  }
};

// All integer points p with |p|^2 = r2 (the "cospherical" pools).
template <int D>
std::vector<Point<D>> integer_sphere(int r2) {
  std::vector<Point<D>> out;
  const int r = static_cast<int>(std::sqrt(static_cast<double>(r2))) + 1;
  std::array<int, D> c;
  c.fill(-r);
  while (true) {
    int s = 0;
    for (int x : c) s += x * x;
    if (s == r2) {
      Point<D> p;
      for (int k = 0; k < D; ++k) p[k] = c[k];
      out.push_back(p);
    }
    int k = 0;
    while (k < D && c[k] == r) c[k++] = -r;
    if (k == D) break;
    ++c[k];
  }
  return out;
}

// The vertices of the cube [-1, 1]^D.
template <int D>
std::vector<Point<D>> cube_vertices() {
  std::vector<Point<D>> out;
  for (int m = 0; m < (1 << D); ++m) {
    Point<D> p;
    for (int k = 0; k < D; ++k) p[k] = (m >> k) & 1 ? 1.0 : -1.0;
    out.push_back(p);
  }
  return out;
}

// A pool of vertices: coordinates that stay put plus distinct ids in a random order (so the id order
// is unrelated to the argument order).
template <int D>
struct Pool {
  std::vector<Point<D>> pts;
  std::vector<uint32_t> ids;

  Pool(std::vector<Point<D>> points, Rng& rng) : pts(std::move(points)), ids(pts.size()) {
    std::iota(ids.begin(), ids.end(), 0u);
    std::shuffle(ids.begin(), ids.end(), rng);
    for (auto& id : ids) id = id * 7 + 3;  // not contiguous, not starting at 0
  }
  std::size_t size() const { return pts.size(); }
  pr::Vertex vertex(std::size_t i) const { return {pts[i].data(), ids[i]}; }

  // N distinct vertices picked at random.
  template <int N>
  std::array<pr::Vertex, N> pick(Rng& rng) const {
    std::array<std::size_t, N> idx;
    for (int i = 0; i < N; ++i) {
      bool fresh;
      do {
        idx[i] = std::uniform_int_distribution<std::size_t>(0, pts.size() - 1)(rng);
        fresh = std::find(idx.begin(), idx.begin() + i, idx[i]) == idx.begin() + i;
      } while (!fresh);
    }
    std::array<pr::Vertex, N> v;
    for (int i = 0; i < N; ++i) v[i] = vertex(idx[i]);
    return v;
  }
};

template <int D>
std::vector<Point<D>> grid_box(int lo, int hi) {
  std::vector<Point<D>> out;
  std::array<int, D> c;
  c.fill(lo);
  while (true) {
    Point<D> p;
    for (int k = 0; k < D; ++k) p[k] = c[k];
    out.push_back(p);
    int k = 0;
    while (k < D && c[k] == hi) c[k++] = lo;
    if (k == D) break;
    ++c[k];
  }
  return out;
}

// A random subset of `count` points of a pool (or the whole pool if smaller).
template <int D>
std::vector<Point<D>> sample(std::vector<Point<D>> all, std::size_t count, Rng& rng) {
  std::shuffle(all.begin(), all.end(), rng);
  if (all.size() > count) all.resize(count);
  return all;
}

}  // namespace sweepcdt::testutil
