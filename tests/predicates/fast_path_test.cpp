// The exact-zero fast paths of the predicates (orientation.cpp: equal points, collinear triples; ray_box.cpp: a zero
// factor in both products of the slab comparison) and the sign-magnitude fixed-width exact stage
// (wide_int.h), against the rational reference, on inputs built to hit them and to sit just beside
// them: exact zeros, 1-ulp neighbours, huge, tiny and subnormal magnitudes.
#include <cmath>
#include <limits>

#include <gmpxx.h>

#include "predicate_test_util.h"
#include "wide_int.h"
#include "sweepcdt/predicates/ray_box.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
using pr::Sign;

// Scales that keep every difference admissible to the filters (<= 2^64) or push it to the exact
// stage, and tiny ones whose products underflow.
constexpr double kScales[] = {1.0, 0x1p-30, 0x1p40, 0x1p-1000, 0x1p-1060, 0x1p900, 3.0e-310};

template <int D>
Point<D> scaled(const Point<D>& p, double s) {
  Point<D> q;
  for (int k = 0; k < D; ++k) q[k] = p[k] * s;
  return q;
}

template <int D>
void check_orient_insphere(const std::array<Point<D>, D + 2>& pts, FailureBudget& budget, int& zeros) {
  pr::Coords<D + 2> all;
  for (int i = 0; i < D + 2; ++i) all[i] = pts[i].data();
  pr::Coords<D + 1> simplex;
  std::copy(all.begin(), all.begin() + D + 1, simplex.begin());
  const auto v = vecs<D>(all);
  const int eo = ref::orient({v.begin(), v.begin() + D + 1});
  const int ei = ref::insphere(v);
  zeros += eo == 0 || ei == 0;
  if (pr::to_int(pr::orient<D>(simplex)) != eo && budget.fail())
    ADD_FAILURE() << "orient<" << D << "> expected " << sign_name(eo) << "\n" << dump<D>(simplex);
  if (pr::to_int(pr::insphere<D>(all)) != ei && budget.fail())
    ADD_FAILURE() << "insphere<" << D << "> expected " << sign_name(ei) << "\n" << dump<D>(all);
}

// Random and grid points that `degenerate(pts, rng)` makes an exact zero of one of the fast paths,
// returning a point and a coordinate of it; in two cases of three that coordinate is then moved by
// one ulp up or down (no longer degenerate: the exact stage decides). At every scale, orient and
// insphere against the rational reference.
template <int D, class Degenerate>
void nudged_degeneracies(uint32_t seed, int cases, Degenerate&& degenerate) {
  Rng rng(seed);
  FailureBudget budget;
  int zeros = 0;
  for (int n = 0; n < cases; ++n) {
    std::array<Point<D>, D + 2> pts;
    for (auto& p : pts) p = n % 2 ? random_point<D>(rng) : grid_point<D>(rng, -4, 4);
    const auto [j, k] = degenerate(pts, rng);
    const double s = kScales[n % std::size(kScales)];
    for (auto& p : pts) p = scaled<D>(p, s);
    const double inf = std::numeric_limits<double>::infinity();
    if (const int mode = n % 3; mode != 0) pts[j][k] = std::nextafter(pts[j][k], mode == 1 ? inf : -inf);
    check_orient_insphere<D>(pts, budget, zeros);
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(zeros, cases / 4) << "too few exact zeros: " << zeros << " of " << cases;
}

// One point copied onto another: orient and insphere are zero (the equal-points fast path).
template <int D>
void equal_points_case() {
  nudged_degeneracies<D>(0xfa570000 + D, 600, [](std::array<Point<D>, D + 2>& pts, Rng& rng) {
    const int i = uniform_int(rng, 0, D + 1), j = (i + uniform_int(rng, 1, D + 1)) % (D + 2);
    pts[j] = pts[i];
    return std::pair{j, uniform_int(rng, 0, D - 1)};
  });
}

TEST(FastPath, EqualPointsOrientInsphere2) { equal_points_case<2>(); }
TEST(FastPath, EqualPointsOrientInsphere3) { equal_points_case<3>(); }

// Every point with one coordinate equal (an axis-parallel line or plane): orient is zero (the
// shared-coordinate fast path); the nudge moves that coordinate of one of the simplex's points.
template <int D>
void shared_coordinate_case() {
  nudged_degeneracies<D>(0x5ca7e000 + D, 900, [](std::array<Point<D>, D + 2>& pts, Rng& rng) {
    const int k = uniform_int(rng, 0, D - 1);
    for (auto& p : pts) p[k] = pts[0][k];
    return std::pair{uniform_int(rng, 0, D), k};
  });
}

TEST(FastPath, SharedCoordinateOrient2) { shared_coordinate_case<2>(); }
TEST(FastPath, SharedCoordinateOrient3) { shared_coordinate_case<3>(); }

// Case n of the triples below: points 0..2 a, b, c (c on ab or one ulp off it), the rest random.
template <std::size_t N>
std::array<Point<3>, N> steiner_like_triple(Rng& rng, int n) {
  std::array<Point<3>, N> pts;
  for (auto& p : pts)
    for (int k = 0; k < 3; ++k) p[k] = n % 2 ? static_cast<float>(uniform(rng, -100.0, 100.0)) : uniform_int(rng, -8, 8);
  const double t = uniform_int(rng, 1, (1 << 20) - 1) / double(1 << 20);
  for (int k = 0; k < 3; ++k) pts[2][k] = pts[0][k] + t * (pts[1][k] - pts[0][k]);
  if (n % 3 == 1) pts[2][n % 7 % 3] = std::nextafter(pts[2][n % 7 % 3], 1e300);
  if (n % 3 == 2) pts[2][n % 5 % 3] = std::nextafter(pts[2][n % 5 % 3], -1e300);
  if (n % 4 == 3) {  // b - a = (1, 3, 0), c - a = (x, fl(3x), 0): the products 3x and fl(3x) differ only below rounding
    const double x = 1 + uniform_int(rng, 0, 1 << 20) * 0x1p-51 + 0x1p-52;
    pts[0] = {0, 0, 0};
    pts[1] = {1, 3, 0};
    pts[2] = {x, 3 * x, 0};
  }
  return pts;
}

// Three of orient3's four points on one line (orientation.cpp's collinear fast path): c = a + t (b - a)
// with t of few bits, as Steiner points split segments, on float-like and grid coordinates — exactly
// collinear where the arithmetic was exact, not quite where it rounded — and c moved by one ulp
// (not collinear: the products of the cross product then differ, often only in their remainders),
// in every position among the four, at every scale (where tiny or huge differences make the fast
// path stand aside), against the rational reference.
TEST(FastPath, CollinearTriplesOrient3) {
  Rng rng(0xc0111);
  FailureBudget budget;
  int zeros = 0, cases = 0;
  for (int n = 0; n < 3000; ++n) {
    std::array<Point<3>, 5> pts = steiner_like_triple<5>(rng, n);
    std::swap(pts[uniform_int(rng, 0, 3)], pts[uniform_int(rng, 0, 3)]);  // the triple anywhere among the four
    std::swap(pts[uniform_int(rng, 0, 3)], pts[uniform_int(rng, 0, 3)]);
    const double s = kScales[n % std::size(kScales)];
    for (auto& p : pts) p = scaled<3>(p, s);
    check_orient_insphere<3>(pts, budget, zeros);
    ++cases;
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(zeros, cases / 6) << "too few exact zeros: " << zeros << " of " << cases;
}

// collinear<3>'s fast "yes" (exactly_collinear: exact differences, then the cross product's
// products compared exactly) on the same triples: Steiner-like points c = a + t (b - a), exactly on
// the line where the arithmetic was exact, nudged by one ulp, products that differ only in their
// remainders, at every scale, against the rational reference (each projection's orientation zero).
TEST(FastPath, CollinearTriples) {
  Rng rng(0xc0112);
  int on_line = 0, off_line = 0;
  for (int n = 0; n < 3000; ++n) {
    std::array<Point<3>, 3> pts = steiner_like_triple<3>(rng, n);
    std::swap(pts[uniform_int(rng, 0, 2)], pts[uniform_int(rng, 0, 2)]);
    const double s = kScales[n % std::size(kScales)];
    for (auto& p : pts) p = scaled<3>(p, s);
    bool expected = true;
    for (int i = 0; i < 3 && expected; ++i)
      for (int j = i + 1; j < 3 && expected; ++j) {
        std::vector<ref::Vec> q;
        for (const auto& p : pts) q.push_back({ref::exact(p[i]), ref::exact(p[j])});
        expected = ref::orient(q) == 0;
      }
    ASSERT_EQ(pr::collinear<3>(pts[0].data(), pts[1].data(), pts[2].data()), expected)
        << dump<3>(std::array<const double*, 3>{pts[0].data(), pts[1].data(), pts[2].data()});
    (expected ? on_line : off_line)++;
  }
  EXPECT_GT(on_line, 500);
  EXPECT_GT(off_line, 500);
}

// orient2's and orient3's small-range exact stage (orient_small.h): coordinates that are multiples
// of 2^low below 2^(low + 61) — D + 1 points of a hyperplane with float coordinates (the last an
// affine combination with few-bit weights, as Steiner points are), or lattice points on one — exactly
// 0 by construction, their 1-ulp neighbours, and sets whose binary range is 60 to 64 bits (beyond 61
// the general stage decides) with determinants near the limit, against the rational reference.
template <int D>
void small_range_case(uint64_t seed) {
  Rng rng(seed);
  FailureBudget budget;
  int zeros = 0, cases = 0;
  for (int n = 0; n < 6000; ++n) {
    std::array<Point<D>, D + 2> pts;
    const int kind = n % 4;
    if (kind == 0) {  // p_D = p_0 + sum of w_i (p_i - p_0), w_1 of 20 bits, the others of 6
      for (int i = 0; i < D; ++i)
        for (int k = 0; k < D; ++k) pts[i][k] = static_cast<float>(uniform(rng, -200.0, 200.0));
      pts[D] = pts[0];
      for (int i = 1; i < D; ++i) {
        const double w = i == 1 ? uniform_int(rng, 1, (1 << 20) - 1) / double(1 << 20) : uniform_int(rng, -64, 64) / 64.0;
        for (int k = 0; k < D; ++k) pts[D][k] += w * (pts[i][k] - pts[0][k]);
      }
    } else if (kind == 1) {  // lattice points on the hyperplane x_0 + 2 x_1 - 3 x_2 ... = c
      const double c = uniform_int(rng, -20, 20);
      for (int i = 0; i <= D; ++i) {
        pts[i][0] = c;
        for (int k = 1; k < D; ++k) {
          pts[i][k] = uniform_int(rng, -1000, 1000);
          pts[i][0] -= (k % 2 ? 2 : -3) * pts[i][k];
        }
      }
    } else {  // a binary range of 60 to 64 bits: 2^(range - 1) beside 1, and large random integers
      const int range = 60 + n % 5;
      for (int i = 0; i <= D; ++i)
        for (int k = 0; k < D; ++k) {
          const double big = std::ldexp(1.0, range - 1) - std::ldexp(1.0, range - 53) * uniform_int(rng, 0, 1 << 20);
          pts[i][k] = (uniform_int(rng, 0, 1) ? 1 : -1) * (uniform_int(rng, 0, 3) == 0 ? 1.0 : big);
        }
      if (kind == 3) pts[D] = pts[uniform_int(rng, 0, D - 1)], pts[D][uniform_int(rng, 0, D - 1)] = 1.0;  // near a duplicate
    }
    if (n % 5 == 1) pts[n % (D + 1)][n % D] = std::nextafter(pts[n % (D + 1)][n % D], 1e300);
    if (n % 5 == 2) pts[n % (D + 1)][n % D] = std::nextafter(pts[n % (D + 1)][n % D], -1e300);
    pts[D + 1] = pts[0];
    std::swap(pts[uniform_int(rng, 0, D)], pts[uniform_int(rng, 0, D)]);
    const double scale = n % 7 == 0 ? 0x1p-30 : n % 7 == 1 ? 0x1p40 : 1.0;
    for (auto& p : pts) p = scaled<D>(p, scale);
    check_orient_insphere<D>(pts, budget, zeros);
    ++cases;
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(zeros, cases / 5) << "too few exact zeros: " << zeros << " of " << cases;
}

TEST(FastPath, SmallRangeOrient2) { small_range_case<2>(0x5a12); }
TEST(FastPath, SmallRangeOrient3) { small_range_case<3>(0x5a11); }

// Coordinates whose binary range exceeds 62 bits — CAD parts put 50.0 beside rounding residues such
// as 3.67e-15 (r cos 90 degrees) — go to the fixed-width stage as multi-limb integers (ShiftedArith in
// arith.h) instead of GMP. Exactly coplanar/cospherical sets (one coordinate shared by all points, so
// orient is 0), their 1-ulp neighbours, and random mixes, against the rational reference.
template <int D>
void wide_range_case() {
  Rng rng(0x71de0000 + D);
  FailureBudget budget;
  int zeros = 0, cases = 0;
  const double residues[] = {3.673940187178589e-15, -9.797174820681343e-16, 6.123233995736766e-17, 0x1.8p-80};
  const double large[] = {50.0, -37.5, 25.123456789, 0x1.fffffffffffffp+9};
  for (int n = 0; n < 900; ++n) {
    std::array<Point<D>, D + 2> pts;
    for (auto& p : pts)
      for (int k = 0; k < D; ++k) {
        const int pick = uniform_int(rng, 0, 3);
        p[k] = pick == 0   ? residues[uniform_int(rng, 0, 3)] * uniform_int(rng, -3, 3)
               : pick == 1 ? large[uniform_int(rng, 0, 3)]
                           : uniform(rng, -50.0, 50.0);
      }
    const int mode = n % 3;  // 0: random, 1: all on the plane x_k = c (orient 0), 2: that, one ulp off
    if (mode != 0) {
      const int k = uniform_int(rng, 0, D - 1);
      const double c = residues[uniform_int(rng, 0, 3)];
      for (auto& p : pts) p[k] = c;
      if (mode == 2) pts[uniform_int(rng, 0, D)][k] = std::nextafter(c, 1.0);
    }
    check_orient_insphere<D>(pts, budget, zeros);
    ++cases;
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(zeros, cases / 4) << "too few exact zeros: " << zeros << " of " << cases;
}

TEST(FastPath, WideBinaryRangeOrientInsphere2) { wide_range_case<2>(); }
TEST(FastPath, WideBinaryRangeOrientInsphere3) { wide_range_case<3>(); }
TEST(FastPath, WideBinaryRangeOrientInsphere4) { wide_range_case<4>(); }

// Int192 (wide_int.h) on its own, against GMP: products whose factors have up to 189 bits between
// them (so every limb of either factor is used, a product stays below 2^190), sums and differences,
// of every sign, with runs of one bits (carries and borrows across the limbs) and at random. Values
// go in and out as two's complement limbs.
TEST(FastPath, Int192ArithmeticAgainstGmp) {
  namespace d = pr::detail;
  const mpz_class modulus = mpz_class(1) << 192;
  const auto value_of = [&](const d::Int192& x) {
    mpz_class v = 0;
    for (int k = 2; k >= 0; --k) v = (v << 64) + mpz_class(static_cast<unsigned long>(x.limb[k]));
    return x.limb[2] >> 63 ? mpz_class(v - modulus) : v;
  };
  const auto int192_of = [&](const mpz_class& v) {
    mpz_class u = v < 0 ? mpz_class(v + modulus) : v;
    d::Int192 x;
    for (int k = 0; k < 3; ++k) {
      x.limb[k] = mpz_class(u & ((mpz_class(1) << 64) - 1)).get_ui();
      u >>= 64;
    }
    return x;
  };
  gmp_randclass random(gmp_randinit_default);
  random.seed(0x192);
  Rng rng(0x192);
  for (int n = 0; n < 20000; ++n) {
    mpz_class v[2];
    const int first_bits = uniform_int(rng, 1, 188);
    for (mpz_class& x : v) {
      const int bits = &x == &v[0] ? first_bits : uniform_int(rng, 1, 189 - first_bits);
      x = uniform_int(rng, 0, 3) == 0 ? mpz_class((mpz_class(1) << bits) - 1) : mpz_class(random.get_z_bits(bits));
      if (uniform_int(rng, 0, 1)) x = -x;
    }
    const d::Int192 a = int192_of(v[0]), b = int192_of(v[1]);
    ASSERT_EQ(value_of(d::Int192::from_int64(-n)), -n);
    ASSERT_EQ(value_of(a * b), v[0] * v[1]) << n;
    ASSERT_EQ(value_of(a + b), v[0] + v[1]) << n;
    ASSERT_EQ(value_of(a - b), v[0] - v[1]) << n;
    ASSERT_EQ(value_of(-a), -v[0]) << n;
    ASSERT_EQ((a * b).sign(), sgn(v[0] * v[1])) << n;
    ASSERT_EQ((a - b).sign(), sgn(v[0] - v[1])) << n;
  }
}

// Float coordinates of CAD parts and scans: a few dozen bits of binary range, so a 3D insphere test
// needs 128 to 192 bits (the two's complement Int192 of wide_int.h). Their exact calls are mostly
// exact zeros: a hole's circle on the top and bottom face lies on one sphere. Points on such pairs
// of circles (Pythagorean offsets, so exactly on them) about float centres at several scales, one
// coordinate moved by one float ulp in two cases of three, and random float points; orient and
// insphere against the rational reference.
TEST(FastPath, FloatCadCoordinatesOrientInsphere3) {
  Rng rng(0xf10a7);
  FailureBudget budget;
  int zeros = 0;
  const int offsets[][2] = {{3, 4}, {4, 3}, {-3, 4}, {5, 0}, {0, -5}, {-4, -3}, {3, -4}, {-5, 0}};
  for (int n = 0; n < 1500; ++n) {
    const double unit = std::ldexp(1.0, uniform_int(rng, -17, -8));  // the offsets' scale: floats stay floats
    Point<3> centre;
    for (double& c : centre) c = std::round(uniform(rng, -60.0, 60.0) / unit) * unit;
    const double height = uniform_int(rng, 1, 6) * unit;
    std::array<Point<3>, 5> pts;
    for (auto& p : pts) {
      if (n % 5 == 4) {  // random floats
        for (double& x : p) x = static_cast<float>(uniform(rng, -60.0, 60.0));
        continue;
      }
      const auto& o = offsets[uniform_int(rng, 0, 7)];
      p = {centre[0] + o[0] * unit, centre[1] + o[1] * unit, centre[2] + (uniform_int(rng, 0, 1) ? height : -height)};
      for (const double x : p) ASSERT_EQ(static_cast<double>(static_cast<float>(x)), x) << "not a float: the test is wrong";
    }
    if (const int mode = n % 3; mode != 0) {
      double& x = pts[uniform_int(rng, 0, 4)][uniform_int(rng, 0, 2)];
      x = std::nextafter(static_cast<float>(x), mode == 1 ? 1e30f : -1e30f);
    }
    check_orient_insphere<3>(pts, budget, zeros);
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(zeros, 150) << "too few exact zeros";
}

// Non-finite input is not an exact zero: the exact stage still reports it.
TEST(FastPath, EqualNonFinitePointsAreNotZero) {
  const double inf = std::numeric_limits<double>::infinity();
  const Point<3> a{inf, 0, 0}, b{0, 1, 0}, c{0, 0, 1};
  const pr::Coords<4> p{a.data(), a.data(), b.data(), c.data()};
  EXPECT_ANY_THROW(pr::orient<3>(p));
}

// ray_meets_box on the sphere against an exact slab test: x(t) = v + t (Delta_0 - v); the box is
// met iff on every axis with d_k = 0, lo_k <= v_k <= hi_k, and the latest entry <= the earliest exit
// with the exit at t >= 0.
template <int D>
bool reference_meets(const double* v, const double* target, const double* lo, const double* hi) {
  bool have = false;
  ref::Q entry, exit;
  for (int k = 0; k < D; ++k) {
    const ref::Q vk = ref::exact(v[k]), d = ref::exact(target[k]) - vk;
    if (ref::sign(d) == 0) {
      if (v[k] < lo[k] || v[k] > hi[k]) return false;
      continue;
    }
    ref::Q a = (ref::exact(lo[k]) - vk) / d, b = (ref::exact(hi[k]) - vk) / d;
    if (b < a) std::swap(a, b);
    if (!have || a > entry) entry = a;
    if (!have || b < exit) exit = b;
    have = true;
  }
  return !have || (ref::sign(exit) >= 0 && entry <= exit);
}

template <int D>
void ray_box_case() {
  Rng rng(0xfa571000 + D);
  FailureBudget budget;
  int met = 0, missed = 0;
  for (int n = 0; n < 4000; ++n) {
    const double s = kScales[n % std::size(kScales)];
    std::array<Point<D>, D + 1> seed;
    pr::Coords<D + 1> delta;
    for (int j = 0; j <= D; ++j) {
      seed[j] = scaled<D>(grid_point<D>(rng, -3, 3), s);
      delta[j] = seed[j].data();
    }
    Point<D> v = scaled<D>(grid_point<D>(rng, -3, 3), s);
    Point<D> lo = scaled<D>(grid_point<D>(rng, -3, 3), s), hi = lo;
    for (int k = 0; k < D; ++k) {
      hi[k] = lo[k] + s * uniform_int(rng, 0, 3);
      // Box sides through v (the face in the box has v as a vertex) or through Delta_0, or 1 ulp off.
      const int r = uniform_int(rng, 0, 5);
      if (r == 0) lo[k] = v[k];
      if (r == 1) hi[k] = v[k];
      if (r == 2) lo[k] = seed[0][k];
      if (r == 3) lo[k] = std::nextafter(v[k], -INFINITY), hi[k] = std::max(hi[k], lo[k]);
      if (hi[k] < lo[k]) std::swap(lo[k], hi[k]);
    }
    const bool expected = reference_meets<D>(v.data(), seed[0].data(), lo.data(), hi.data());
    const bool got = pr::ray_meets_box<D>(pr::SphereSweep<D>{delta}, v.data(), lo.data(), hi.data());
    (expected ? met : missed)++;
    if (got != expected && budget.fail())
      ADD_FAILURE() << "ray_meets_box<" << D << "> expected " << expected << "\n" << dump_point<D>("v", v.data())
                    << dump_point<D>("delta0", seed[0].data()) << dump_point<D>("lo", lo.data())
                    << dump_point<D>("hi", hi.data());
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(met, 200);
  EXPECT_GT(missed, 200);
}

TEST(FastPath, RayMeetsBoxSphere2) { ray_box_case<2>(); }
TEST(FastPath, RayMeetsBoxSphere3) { ray_box_case<3>(); }
TEST(FastPath, RayMeetsBoxSphere4) { ray_box_case<4>(); }

}  // namespace
