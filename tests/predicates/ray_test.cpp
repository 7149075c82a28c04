// ray_hits and compare_hits (paper §3, drop faces) against a rational ray/simplex intersection with
// the concretely perturbed direction  d = -(e_1 + delta e_2 + delta^2 e_3 + ...)  (sweep plane) or
// d = (Delta_0 - v) + delta (Delta_1 - v) + ...  (sweep sphere), delta = 2^-100, on integer grids
// where the unperturbed ray would graze face boundaries all the time.
#include "predicate_test_util.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
using pr::Sign;

template <int D>
using Face = std::array<Point<D>, D>;

template <int D>
pr::Coords<D> coords(const Face<D>& f) {
  pr::Coords<D> c;
  for (int i = 0; i < D; ++i) c[i] = f[i].data();
  return c;
}

// A seed simplex Delta of random points of the grid [-3, 3]^D, not flat (exactly); `seed` holds the
// points that `delta` points into.
template <int D>
pr::Coords<D + 1> grid_seed(Rng& rng, std::array<Point<D>, D + 1>& seed) {
  pr::Coords<D + 1> delta;
  do {
    for (int j = 0; j <= D; ++j) {
      seed[j] = grid_point<D>(rng, -3, 3);
      delta[j] = seed[j].data();
    }
  } while (ref::orient(vecs<D>(delta)) == 0);
  return delta;
}

enum class RefHit { Miss, Hit, Boundary };

struct RefStrike {
  RefHit kind = RefHit::Miss;
  ref::Q t;
};

template <int D>
RefStrike reference_strike(const ref::Vec& v, const ref::Vec& d, const Face<D>& f) {
  const ref::LineFace x = ref::line_face(v, d, vecs<D>(coords<D>(f)));
  RefStrike r;
  if (x.parallel || ref::sign(x.t) <= 0) return r;
  r.t = x.t;
  bool boundary = false;
  for (const auto& l : x.lambda) {
    if (ref::sign(l) < 0) return r;
    boundary |= ref::sign(l) == 0;
  }
  r.kind = boundary ? RefHit::Boundary : RefHit::Hit;
  return r;
}

struct RayStats {
  int faces = 0, hits = 0, skipped = 0, pairs = 0, equal_pairs = 0;
};

template <int D, class Sweep>
std::string describe(const Sweep& sweep, const Point<D>& v) {
  std::string s = dump_point<D>("v", v.data());
  if constexpr (!std::is_same_v<Sweep, pr::PlaneSweep>) s += "delta:\n" + dump<D>(sweep.delta);
  return s;
}

// One ray: faces around a point ahead of v (plus coplanar siblings of the faces it strikes), checked
// one by one with ray_hits and pairwise with compare_hits.
template <int D, class Sweep>
void check_ray(const Sweep& sweep, const Point<D>& v, const ref::Vec& dir, const Point<D>& ahead, Rng& rng,
               int faces, RayStats& stats, FailureBudget& budget) {
  const ref::Vec vv = vec<D>(v.data());
  std::vector<Face<D>> pool;
  for (int n = 0; n < faces; ++n) {
    Face<D> f;
    for (auto& x : f) {
      x = grid_point<D>(rng, -2, 2);
      for (int k = 0; k < D; ++k) x[k] += ahead[k];
    }
    pool.push_back(f);
  }
  std::vector<std::pair<Face<D>, ref::Q>> struck;
  for (std::size_t n = 0; n < pool.size(); ++n) {
    const Face<D> f = pool[n];
    if (!ref::hyperplane_through(vecs<D>(coords<D>(f)))) continue;  // a face must span a hyperplane
    ++stats.faces;
    const RefStrike e = reference_strike<D>(vv, dir, f);
    if (e.kind == RefHit::Boundary) {
      ++stats.skipped;
      continue;
    }
    const bool expected = e.kind == RefHit::Hit;
    const bool got = pr::ray_hits<D>(sweep, v.data(), coords<D>(f));
    if (got != expected && budget.fail())
      ADD_FAILURE() << "ray_hits<" << D << "> expected " << expected << ", got " << got << "\n"
                    << describe<D>(sweep, v) << "f:\n" << dump<D>(coords<D>(f));
    if (!expected) continue;
    ++stats.hits;
    struck.emplace_back(f, e.t);
    if (n < static_cast<std::size_t>(faces)) {
      // A coplanar sibling: f_j moved by f_a - f_b stays in the hyperplane (and on the grid).
      Face<D> g = f;
      const int j = uniform_int(rng, 0, D - 1), a = uniform_int(rng, 0, D - 1), b = uniform_int(rng, 0, D - 1);
      for (int k = 0; k < D; ++k) g[j][k] += f[a][k] - f[b][k];
      pool.push_back(g);
    }
  }
  for (std::size_t i = 0; i < struck.size(); ++i) {
    for (std::size_t j = i; j < struck.size(); ++j) {
      const int expected = cmp(struck[i].second, struck[j].second) < 0 ? -1 : cmp(struck[i].second, struck[j].second) > 0;
      const auto f1 = coords<D>(struck[i].first), f2 = coords<D>(struck[j].first);
      const Sign got = pr::compare_hits<D>(sweep, v.data(), f1, f2);
      ++stats.pairs;
      stats.equal_pairs += expected == 0 && i != j;
      if (pr::to_int(got) != expected && budget.fail())
        ADD_FAILURE() << "compare_hits<" << D << "> expected " << sign_name(expected) << ", got " << sign_name(got)
                      << "\n" << describe<D>(sweep, v) << "f1:\n" << dump<D>(f1) << "f2:\n" << dump<D>(f2);
      if (pr::compare_hits<D>(sweep, v.data(), f2, f1) != -got && budget.fail())
        ADD_FAILURE() << "compare_hits<" << D << "> not antisymmetric\n" << describe<D>(sweep, v) << "f1:\n"
                      << dump<D>(f1) << "f2:\n" << dump<D>(f2);
    }
  }
}

template <class T>
class Ray : public ::testing::Test {};
TYPED_TEST_SUITE(Ray, Dim2to5, DimName);

void expect_coverage(const RayStats& s) {
  EXPECT_GT(s.hits, 100) << "too few strikes to test";
  EXPECT_LT(s.skipped, s.faces / 20) << "too many exact boundary cases skipped: " << s.skipped << " of " << s.faces;
  EXPECT_GT(s.equal_pairs, 10) << "too few coplanar pairs";
}

TYPED_TEST(Ray, PlaneSweepOnGrid) {
  constexpr int D = TypeParam::value;
  Rng rng(0x7a900001 + D);
  const ref::Vec dir = ref::plane_direction(D, ref::ray_delta());
  FailureBudget budget;
  RayStats stats;
  for (int round = 0; round < 60; ++round) {
    const Point<D> v = grid_point<D>(rng, -2, 2);
    Point<D> ahead = v;
    ahead[0] -= uniform_int(rng, 1, 3);
    check_ray<D>(pr::PlaneSweep{}, v, dir, ahead, rng, D <= 3 ? 60 : 150, stats, budget);
  }
  EXPECT_EQ(budget.failures, 0) << stats.faces << " faces, " << stats.hits << " strikes, " << stats.pairs << " pairs";
  expect_coverage(stats);
}

TYPED_TEST(Ray, SphereSweepOnGrid) {
  constexpr int D = TypeParam::value;
  Rng rng(0x7a900002 + D);
  FailureBudget budget;
  RayStats stats;
  for (int round = 0; round < 60; ++round) {
    std::array<Point<D>, D + 1> seed;
    const pr::Coords<D + 1> delta = grid_seed<D>(rng, seed);
    const pr::SphereSweep<D> sweep{delta};
    // Sometimes v is Delta_0 itself (the ray then heads for Delta_1), or on a line with Delta_0.
    Point<D> v = round % 10 == 0 ? seed[0] : grid_point<D>(rng, -3, 3);
    const ref::Vec dir = ref::sphere_direction(vec<D>(v.data()), vecs<D>(delta), ref::ray_delta());
    const Point<D>& target = v == seed[0] ? seed[1] : seed[0];
    Point<D> ahead;
    for (int k = 0; k < D; ++k) ahead[k] = std::round((v[k] + target[k]) / 2);
    check_ray<D>(sweep, v, dir, ahead, rng, D <= 3 ? 60 : 150, stats, budget);
  }
  EXPECT_EQ(budget.failures, 0) << stats.faces << " faces, " << stats.hits << " strikes, " << stats.pairs << " pairs";
  expect_coverage(stats);
}

// Faces through a seed vertex: every ray toward Delta_0 strikes them all at t = 1, so compare_hits
// skips the delta^j terms that vanish identically (both faces through Delta_j, ray.cpp) and must
// still order them as the perturbed ray does. Delta_1 is sometimes a vertex of the faces too.
TYPED_TEST(Ray, SphereSweepFacesThroughSeedVertex) {
  constexpr int D = TypeParam::value;
  Rng rng(0x7a900004 + D);
  FailureBudget budget;
  RayStats stats;
  for (int round = 0; round < 80; ++round) {
    std::array<Point<D>, D + 1> seed;
    const pr::Coords<D + 1> delta = grid_seed<D>(rng, seed);
    const pr::SphereSweep<D> sweep{delta};
    const Point<D> v = grid_point<D>(rng, -3, 3);
    if (v == seed[0]) continue;
    const ref::Vec vv = vec<D>(v.data());
    const ref::Vec dir = ref::sphere_direction(vv, vecs<D>(delta), ref::ray_delta());
    std::vector<std::pair<Face<D>, ref::Q>> struck;
    for (int n = 0; n < 40; ++n) {
      Face<D> f;
      f[0] = seed[0];
      for (int i = 1; i < D; ++i) f[i] = (i == 1 && n % 3 == 0) ? seed[1] : grid_point<D>(rng, -3, 3);
      if (!ref::hyperplane_through(vecs<D>(coords<D>(f)))) continue;
      ++stats.faces;
      const RefStrike e = reference_strike<D>(vv, dir, f);
      if (e.kind == RefHit::Boundary) {
        ++stats.skipped;
        continue;
      }
      const bool got = pr::ray_hits<D>(sweep, v.data(), coords<D>(f));
      if (got != (e.kind == RefHit::Hit) && budget.fail())
        ADD_FAILURE() << "ray_hits<" << D << "> expected " << (e.kind == RefHit::Hit) << "\n" << describe<D>(sweep, v)
                      << "f:\n" << dump<D>(coords<D>(f));
      if (e.kind == RefHit::Hit) struck.emplace_back(f, e.t), ++stats.hits;
    }
    for (std::size_t i = 0; i < struck.size(); ++i)
      for (std::size_t j = 0; j < struck.size(); ++j) {
        const int c = cmp(struck[i].second, struck[j].second);
        const int expected = c < 0 ? -1 : c > 0;
        const Sign got = pr::compare_hits<D>(sweep, v.data(), coords<D>(struck[i].first), coords<D>(struck[j].first));
        ++stats.pairs;
        stats.equal_pairs += expected == 0 && i != j;
        if (pr::to_int(got) != expected && budget.fail())
          ADD_FAILURE() << "compare_hits<" << D << "> expected " << sign_name(expected) << ", got " << sign_name(got)
                        << "\n" << describe<D>(sweep, v) << "f1:\n" << dump<D>(coords<D>(struck[i].first))
                        << "f2:\n" << dump<D>(coords<D>(struck[j].first));
      }
  }
  EXPECT_EQ(budget.failures, 0) << stats.faces << " faces, " << stats.hits << " strikes, " << stats.pairs << " pairs";
  EXPECT_GT(stats.pairs, 200) << "too few pairs of struck faces through Delta_0";
}

TYPED_TEST(Ray, RandomDoubles) {
  constexpr int D = TypeParam::value;
  Rng rng(0x7a900003 + D);
  FailureBudget budget;
  int hits = 0;
  for (int n = 0; n < 3000; ++n) {
    const Point<D> v = random_point<D>(rng);
    Face<D> f;
    for (auto& x : f) x = random_point<D>(rng);
    std::array<Point<D>, D + 1> seed;
    pr::Coords<D + 1> delta;
    for (int j = 0; j <= D; ++j) {
      seed[j] = random_point<D>(rng);
      delta[j] = seed[j].data();
    }
    const ref::Vec vv = vec<D>(v.data());
    const RefStrike ep = reference_strike<D>(vv, ref::plane_direction(D, ref::ray_delta()), f);
    const RefStrike es = reference_strike<D>(vv, ref::sphere_direction(vv, vecs<D>(delta), ref::ray_delta()), f);
    const bool gp = pr::ray_hits<D>(pr::PlaneSweep{}, v.data(), coords<D>(f));
    const bool gs = pr::ray_hits<D>(pr::SphereSweep<D>{delta}, v.data(), coords<D>(f));
    hits += gp + gs;
    if ((gp != (ep.kind == RefHit::Hit) || gs != (es.kind == RefHit::Hit)) && budget.fail())
      ADD_FAILURE() << "ray_hits<" << D << ">: plane " << gp << ", sphere " << gs << "\n" << dump_point<D>("v", v.data())
                    << "f:\n" << dump<D>(coords<D>(f)) << "delta:\n" << dump<D>(delta);
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(hits, 10);
}

}  // namespace
