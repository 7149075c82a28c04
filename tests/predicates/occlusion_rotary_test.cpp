// occludes (paper §1 visibility) against a rational segment/simplex intersection, and compare_rotary
// / same_side_of_ridge (paper §3, ridges' circular lists) against a rational projection onto the
// 2-plane orthogonal to the ridge (unnormalised Gram-Schmidt), on random and grid inputs.
#include <memory>

#include "predicate_test_util.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
using pr::Sign;

template <class T>
class Occlusion : public ::testing::Test {};
TYPED_TEST_SUITE(Occlusion, Dim2to5, DimName);

template <int D>
void check_occlusion(bool grid, uint64_t seed, int cases) {
  Rng rng(seed);
  FailureBudget budget;
  int occluded = 0, on_plane = 0;
  for (int n = 0; n < cases; ++n) {
    std::array<Point<D>, D + 2> pts;
    for (auto& x : pts) x = grid ? grid_point<D>(rng, -2, 2) : random_point<D>(rng);
    pr::Coords<D> t;
    for (int i = 0; i < D; ++i) t[i] = pts[i].data();
    const auto tv = vecs<D>(t);
    if (!ref::hyperplane_through(tv)) continue;  // t must be a (D-1)-simplex
    const double* p = pts[D].data();
    const double* q = pts[D + 1].data();
    const bool expected = ref::occludes(tv, vec<D>(p), vec<D>(q));
    occluded += expected;
    on_plane += ref::sign(ref::eval(*ref::hyperplane_through(tv), vec<D>(p))) == 0;
    const bool got = pr::occludes<D>(t, p, q);
    if (got != expected && budget.fail())
      ADD_FAILURE() << "occludes<" << D << "> expected " << expected << ", got " << got << "\nt:\n" << dump<D>(t)
                    << dump_point<D>("p", p) << dump_point<D>("q", q);
    // Symmetric in p and q, and in the order of t's vertices.
    auto t2 = t;
    std::shuffle(t2.begin(), t2.end(), rng);
    if ((pr::occludes<D>(t, q, p) != got || pr::occludes<D>(t2, p, q) != got) && budget.fail())
      ADD_FAILURE() << "occludes<" << D << "> depends on argument order\nt:\n" << dump<D>(t) << dump_point<D>("p", p)
                    << dump_point<D>("q", q);
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(occluded, cases / 200) << "too few occluded cases";
  if (grid) EXPECT_GT(on_plane, 0);
}

TYPED_TEST(Occlusion, RandomDoubles) { check_occlusion<TypeParam::value>(false, 0x0cc10001 + TypeParam::value, 4000); }

TYPED_TEST(Occlusion, IntegerGrid) { check_occlusion<TypeParam::value>(true, 0x0cc10002 + TypeParam::value, 4000); }

// Crossing through a vertex or an edge of t counts (closed simplex); touching the plane does not.
TEST(Occlusion, ClosedSimplexOpenSegment) {
  const double a[] = {0, 0, 0}, b[] = {1, 0, 0}, c[] = {0, 1, 0};
  const pr::Coords<3> t{a, b, c};
  const double above_a[] = {0, 0, 1}, below_a[] = {0, 0, -1}, above_mid[] = {0.5, 0, 1}, below_mid[] = {0.5, 0, -1};
  const double on[] = {0.25, 0.25, 0}, far[] = {2, 2, -1}, far_up[] = {2, 2, 1};
  EXPECT_TRUE(pr::occludes<3>(t, above_a, below_a));
  EXPECT_TRUE(pr::occludes<3>(t, above_mid, below_mid));
  EXPECT_FALSE(pr::occludes<3>(t, on, below_a));
  EXPECT_FALSE(pr::occludes<3>(t, far_up, far));
}

// ---- rotary order -------------------------------------------------------------------------------

template <class T>
class Rotary : public ::testing::Test {};
TYPED_TEST_SUITE(Rotary, Dim2to5, DimName);

template <int D>
bool in_ridge_hull(const ref::RidgeFrame& frame, const Point<D>& x) {
  return ref::is_zero(frame.normal_part(vec<D>(x.data())));
}

template <int D>
void check_rotary(bool grid, uint64_t seed, int ridges, int apexes) {
  Rng rng(seed);
  FailureBudget budget;
  int zeros = 0, half_turns = 0, pairs = 0;
  auto random = [&] { return grid ? grid_point<D>(rng, -2, 2) : random_point<D>(rng); };
  for (int r = 0; r < ridges; ++r) {
    std::array<Point<D>, D - 1> rp;
    pr::Coords<D - 1> ridge;
    std::vector<ref::Vec> rv;
    while (true) {
      rv.clear();
      for (int i = 0; i < D - 1; ++i) {
        rp[i] = random();
        ridge[i] = rp[i].data();
        rv.push_back(vec<D>(ridge[i]));
      }
      try {
        ref::RidgeFrame probe(rv);
        break;
      } catch (const std::invalid_argument&) {
      }
    }
    const ref::RidgeFrame frame(rv);
    std::vector<Point<D>> apex;
    while (static_cast<int>(apex.size()) < apexes) {
      const Point<D> x = random();
      if (in_ridge_hull<D>(frame, x)) continue;
      apex.push_back(x);
      if (grid) {
        // Exactly a half-turn away (reflection through r_0), and at the same angle (shifted along the ridge).
        Point<D> reflected, shifted;
        for (int k = 0; k < D; ++k) {
          reflected[k] = 2 * rp[0][k] - x[k];
          shifted[k] = x[k] + (D > 2 ? rp[D - 2][k] - rp[0][k] : 0.0);
        }
        apex.push_back(reflected);
        apex.push_back(shifted);
      }
    }
    const Point<D> ref_apex = apex[uniform_int(rng, 0, static_cast<int>(apex.size()) - 1)];
    const ref::RotaryReference order(frame, vec<D>(ref_apex.data()));
    for (std::size_t i = 0; i < apex.size(); ++i) {
      for (std::size_t j = 0; j < apex.size(); ++j) {
        const int expected = order.compare(vec<D>(apex[i].data()), vec<D>(apex[j].data()));
        const Sign got = pr::compare_rotary<D>(ridge, ref_apex.data(), apex[i].data(), apex[j].data());
        ++pairs;
        zeros += expected == 0 && i != j;
        half_turns += order.key(vec<D>(apex[i].data())).half == 2;
        if (pr::to_int(got) != expected && budget.fail())
          ADD_FAILURE() << "compare_rotary<" << D << "> expected " << sign_name(expected) << ", got " << sign_name(got)
                        << "\nridge:\n" << dump<D>(ridge) << dump_point<D>("ref", ref_apex.data())
                        << dump_point<D>("a", apex[i].data()) << dump_point<D>("b", apex[j].data());
      }
    }
    // The library's order sorts the apexes into non-decreasing reference angle.
    std::vector<const Point<D>*> sorted;
    for (const auto& x : apex) sorted.push_back(&x);
    std::stable_sort(sorted.begin(), sorted.end(), [&](const Point<D>* a, const Point<D>* b) {
      return pr::compare_rotary<D>(ridge, ref_apex.data(), a->data(), b->data()) == Sign::Negative;
    });
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (order.compare(vec<D>(sorted[i - 1]->data()), vec<D>(sorted[i]->data())) > 0 && budget.fail())
        ADD_FAILURE() << "sorting by compare_rotary<" << D << "> left an inversion\nridge:\n" << dump<D>(ridge);
  }
  EXPECT_EQ(budget.failures, 0) << "of " << pairs << " pairs";
  if (grid) {
    EXPECT_GT(zeros, pairs / 50) << "too few coplanar faces";
    EXPECT_GT(half_turns, 0);
  }
}

TYPED_TEST(Rotary, CompareRotaryOnGrid) { check_rotary<TypeParam::value>(true, 0x707a0001 + TypeParam::value, 25, 12); }

TYPED_TEST(Rotary, CompareRotaryRandomDoubles) {
  check_rotary<TypeParam::value>(false, 0x707a0002 + TypeParam::value, 25, 20);
}

// Points of the hyperplane through the ridge and a: b = r_0 + alpha (a - r_0) + sum beta_i (r_i - r_0)
// with small integers, which is on a's side of the ridge exactly when alpha > 0.
TYPED_TEST(Rotary, SameSideOfRidge) {
  constexpr int D = TypeParam::value;
  Rng rng(0x707a0003 + D);
  FailureBudget budget;
  for (int n = 0; n < 3000; ++n) {
    std::array<Point<D>, D - 1> rp;
    pr::Coords<D - 1> ridge;
    std::vector<ref::Vec> rv;
    for (int i = 0; i < D - 1; ++i) {
      rp[i] = grid_point<D>(rng, -2, 2);
      ridge[i] = rp[i].data();
      rv.push_back(vec<D>(ridge[i]));
    }
    std::unique_ptr<ref::RidgeFrame> frame;
    try {
      frame = std::make_unique<ref::RidgeFrame>(rv);
    } catch (const std::invalid_argument&) {
      continue;
    }
    const Point<D> a = grid_point<D>(rng, -2, 2);
    if (in_ridge_hull<D>(*frame, a)) continue;
    const int alpha = uniform_int(rng, -2, 2);
    Point<D> b;
    for (int k = 0; k < D; ++k) b[k] = rp[0][k] + alpha * (a[k] - rp[0][k]);
    for (int i = 1; i < D - 1; ++i) {
      const int beta = uniform_int(rng, -2, 2);
      for (int k = 0; k < D; ++k) b[k] += beta * (rp[i][k] - rp[0][k]);
    }
    const bool expected = ref::same_side_of_ridge(*frame, vec<D>(a.data()), vec<D>(b.data()));
    ASSERT_EQ(expected, alpha > 0) << "reference disagrees with its construction";
    const bool got = pr::same_side_of_ridge<D>(ridge, a.data(), b.data());
    if (got != expected && budget.fail())
      ADD_FAILURE() << "same_side_of_ridge<" << D << "> expected " << expected << ", got " << got << "\nridge:\n"
                    << dump<D>(ridge) << dump_point<D>("a", a.data()) << dump_point<D>("b", b.data());
  }
  EXPECT_EQ(budget.failures, 0);
}

}  // namespace
