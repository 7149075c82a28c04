// behind_sign and side_of (paper §3) against a rational normal vector n, c with n.f_i = c:
// sweep plane — behind is the side of -infinity along the first axis the hyperplane is not parallel
// to; sweep sphere — behind is the side of the first seed vertex Delta_j off the hyperplane.
#include "predicate_test_util.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
using pr::Sign;

// D affinely independent grid points on a random integer hyperplane parallel to the first `lead`
// axes (lead = 0: a random face; lead >= 1: faces that need the tie-breaking).
template <int D>
std::array<Point<D>, D> face_on(const GridHyperplane<D>& h, Rng& rng) {
  while (true) {
    std::array<Point<D>, D> f;
    std::vector<ref::Vec> v;
    for (auto& x : f) {
      x = h.point(rng, -2, 2);
      v.push_back(vec<D>(x.data()));
    }
    if (ref::hyperplane_through(v)) return f;
  }
}

template <int D>
pr::Coords<D> coords(const std::array<Point<D>, D>& f) {
  pr::Coords<D> c;
  for (int i = 0; i < D; ++i) c[i] = f[i].data();
  return c;
}

// The reference sign of orient(f, x) for a rational point x.
template <int D>
int orient_with(const pr::Coords<D>& f, const ref::Vec& x) {
  auto v = vecs<D>(f);
  v.push_back(x);
  return ref::orient(v);
}

template <class T>
class SweepSides : public ::testing::Test {};
TYPED_TEST_SUITE(SweepSides, Dim2to5, DimName);

TYPED_TEST(SweepSides, PlaneSweepMatchesReference) {
  constexpr int D = TypeParam::value;
  Rng rng(0x51de0001 + D);
  FailureBudget budget;
  std::array<int, D> by_lead{};
  for (int n = 0; n < 3000; ++n) {
    const int lead = n % 3 == 0 ? 0 : uniform_int(rng, 0, D - 1);
    const auto h = GridHyperplane<D>::random(rng, lead);
    const auto fp = n % 5 == 4 ? std::array<Point<D>, D>{} : face_on<D>(h, rng);
    std::array<Point<D>, D> fr;
    if (n % 5 == 4) {  // an unconstrained random grid face
      do {
        for (auto& x : fr) x = grid_point<D>(rng, -2, 2);
      } while (!ref::hyperplane_through(vecs<D>(coords<D>(fr))));
    }
    const auto& face = n % 5 == 4 ? fr : fp;
    const pr::Coords<D> f = coords<D>(face);
    const auto plane = *ref::hyperplane_through(vecs<D>(f));
    int k = 0;
    while (ref::sign(plane.n[k]) == 0) ++k;
    by_lead[k]++;
    // behind_sign: orient(f, x) for x = f_0 - e_k, a point strictly behind.
    ref::Vec behind_point = vec<D>(f[0]);
    behind_point[k] -= 1;
    const int expected_behind = orient_with<D>(f, behind_point);
    const Sign got_behind = pr::behind_sign<D>(pr::PlaneSweep{}, f);
    if (pr::to_int(got_behind) != expected_behind && budget.fail())
      ADD_FAILURE() << "behind_sign<" << D << ">(plane) expected " << sign_name(expected_behind) << ", got "
                    << sign_name(got_behind) << "\n" << dump<D>(f);
    const int eval_behind = ref::behind_eval_sign_plane(plane);
    for (int m = 0; m < 4; ++m) {
      const Point<D> p = m == 0 ? h.point(rng, -2, 2) : grid_point<D>(rng, -3, 3);
      const int expected = ref::side(plane, eval_behind, vec<D>(p.data()));
      const pr::Side got = pr::side_of<D>(pr::PlaneSweep{}, f, p.data());
      if (static_cast<int>(got) != expected && budget.fail())
        ADD_FAILURE() << "side_of<" << D << ">(plane) expected " << expected << ", got " << static_cast<int>(got)
                      << " (-1 behind, 0 on, 1 front)\n" << dump<D>(f) << dump_point<D>("p", p.data());
    }
  }
  EXPECT_EQ(budget.failures, 0);
  for (int k = 1; k < D; ++k) EXPECT_GT(by_lead[k], 50) << "few faces parallel to the first " << k << " axes";
}

TYPED_TEST(SweepSides, SphereSweepMatchesReference) {
  constexpr int D = TypeParam::value;
  Rng rng(0x51de0002 + D);
  FailureBudget budget;
  std::array<int, D + 1> by_first_off{};
  for (int n = 0; n < 3000; ++n) {
    const auto h = GridHyperplane<D>::random(rng, uniform_int(rng, 0, D - 1));
    const auto face = face_on<D>(h, rng);
    const pr::Coords<D> f = coords<D>(face);
    const auto plane = *ref::hyperplane_through(vecs<D>(f));
    // The seed: its first `on` vertices in the face's hyperplane, so that ties are broken further down.
    std::array<Point<D>, D + 1> seed;
    pr::Coords<D + 1> delta;
    const int on = uniform_int(rng, 0, D);
    do {
      for (int j = 0; j <= D; ++j) {
        seed[j] = j < on ? h.point(rng, -2, 2) : grid_point<D>(rng, -2, 2);
        delta[j] = seed[j].data();
      }
    } while (ref::orient(vecs<D>(delta)) == 0);
    const pr::SphereSweep<D> sweep{delta};
    const auto seed_v = vecs<D>(delta);
    int first_off = 0;
    while (ref::sign(ref::eval(plane, seed_v[first_off])) == 0) ++first_off;
    by_first_off[first_off]++;

    const int expected_behind = orient_with<D>(f, seed_v[first_off]);
    const Sign got_behind = pr::behind_sign<D>(sweep, f);
    if (pr::to_int(got_behind) != expected_behind && budget.fail())
      ADD_FAILURE() << "behind_sign<" << D << ">(sphere) expected " << sign_name(expected_behind) << ", got "
                    << sign_name(got_behind) << "\n" << dump<D>(f) << "delta:\n" << dump<D>(delta);
    const int eval_behind = ref::behind_eval_sign_sphere(plane, seed_v);
    for (int m = 0; m < 4; ++m) {
      const Point<D> p = m == 0 ? h.point(rng, -2, 2) : grid_point<D>(rng, -3, 3);
      const int expected = ref::side(plane, eval_behind, vec<D>(p.data()));
      const pr::Side got = pr::side_of<D>(sweep, f, p.data());
      if (static_cast<int>(got) != expected && budget.fail())
        ADD_FAILURE() << "side_of<" << D << ">(sphere) expected " << expected << ", got " << static_cast<int>(got)
                      << " (-1 behind, 0 on, 1 front)\n" << dump<D>(f) << "delta:\n" << dump<D>(delta)
                      << dump_point<D>("p", p.data());
    }
  }
  EXPECT_EQ(budget.failures, 0);
  for (int j = 1; j < D; ++j) EXPECT_GT(by_first_off[j], 30) << "few seeds with " << j << " vertices on the face";
}

// Random doubles: the seed vertices and -infinity are generic, the sides must still match exactly.
TYPED_TEST(SweepSides, RandomDoubles) {
  constexpr int D = TypeParam::value;
  Rng rng(0x51de0003 + D);
  FailureBudget budget;
  for (int n = 0; n < 2000; ++n) {
    std::array<Point<D>, D> face;
    for (auto& x : face) x = random_point<D>(rng);
    std::array<Point<D>, D + 1> seed;
    pr::Coords<D + 1> delta;
    for (int j = 0; j <= D; ++j) {
      seed[j] = random_point<D>(rng);
      delta[j] = seed[j].data();
    }
    const pr::Coords<D> f = coords<D>(face);
    const auto plane = *ref::hyperplane_through(vecs<D>(f));
    const Point<D> p = random_point<D>(rng);
    const ref::Vec pv = vec<D>(p.data());
    const int e_plane = ref::side(plane, ref::behind_eval_sign_plane(plane), pv);
    const int e_sphere = ref::side(plane, ref::behind_eval_sign_sphere(plane, vecs<D>(delta)), pv);
    const int g_plane = static_cast<int>(pr::side_of<D>(pr::PlaneSweep{}, f, p.data()));
    const int g_sphere = static_cast<int>(pr::side_of<D>(pr::SphereSweep<D>{delta}, f, p.data()));
    if ((g_plane != e_plane || g_sphere != e_sphere) && budget.fail())
      ADD_FAILURE() << "side_of<" << D << ">: plane " << g_plane << " (want " << e_plane << "), sphere " << g_sphere
                    << " (want " << e_sphere << ")\n" << dump<D>(f) << "delta:\n" << dump<D>(delta)
                    << dump_point<D>("p", p.data());
  }
  EXPECT_EQ(budget.failures, 0);
}

}  // namespace
