// insphere_perturbed and inside_circumsphere (paper §6) against the rational determinant of
// [[p_i, |p_i|^2 - eps_i, 1]] with concrete eps_i = 2^{-100 (rank_i + 1)}, on exactly cospherical
// integer inputs; plus the identities the header promises.
#include "predicate_test_util.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
using pr::Sign;

template <int D>
std::vector<std::pair<std::string, std::vector<Point<D>>>> degenerate_pools() {
  std::vector<std::pair<std::string, std::vector<Point<D>>>> pools;
  pools.emplace_back("cube vertices", cube_vertices<D>());
  const int r2 = D == 2 ? 25 : D == 3 ? 9 : 4;  // x^2+y^2=25; x^2+y^2+z^2=9 ((+-1,+-2,+-2), (0,0,+-3)); ...
  pools.emplace_back("integer sphere |p|^2=" + std::to_string(r2), integer_sphere<D>(r2));
  pools.emplace_back("grid {-1,0,1}^D", grid_box<D>(-1, 1));
  // Mostly one hyperplane (x_0 = 0), so that all D+2 points are often in it: the only Zero case.
  auto flat = grid_box<D - 1>(-2, 2);
  std::vector<Point<D>> mixed = cube_vertices<D>();
  for (const auto& q : flat) {
    Point<D> p{};
    std::copy(q.begin(), q.end(), p.begin() + 1);
    mixed.push_back(p);
  }
  pools.emplace_back("hyperplane x_0=0 and cube", mixed);
  return pools;
}

template <int D>
int reference_perturbed(const pr::Vertices<D + 2>& p) {
  const ref::EpsTable eps(ids_of(p));
  ref::Vec e;
  for (const auto& v : p) e.push_back(eps(v.id));
  return ref::lifted_insphere(vecs<D>(p), e);
}

template <int D>
bool all_in_one_hyperplane(const pr::Vertices<D + 2>& p) {
  ref::Mat m;
  for (const auto& v : p) {
    ref::Vec row = vec<D>(v.x);
    row.push_back(1);
    m.push_back(row);
  }
  return ref::rank(m) <= D;
}

template <class T>
class Perturbation : public ::testing::Test {};
TYPED_TEST_SUITE(Perturbation, Dim2to5, DimName);

TYPED_TEST(Perturbation, MatchesConcreteEpsilonOnCosphericalInputs) {
  constexpr int D = TypeParam::value;
  Rng rng(0x9e770001 + D);
  for (auto& [name, points] : degenerate_pools<D>()) {
    SCOPED_TRACE(name);
    const Pool<D> pool(points, rng);
    FailureBudget budget;
    int unperturbed_zero = 0, flat = 0;
    const int cases = 2500;
    for (int n = 0; n < cases; ++n) {
      const auto p = pool.template pick<D + 2>(rng);
      const Sign got = pr::insphere_perturbed<D>(p);
      const int expected = reference_perturbed<D>(p);
      unperturbed_zero += pr::insphere<D>(coords_of(p)) == Sign::Zero;
      if (pr::to_int(got) != expected && budget.fail())
        ADD_FAILURE() << "insphere_perturbed<" << D << "> expected " << sign_name(expected) << ", got "
                      << sign_name(got) << "\n" << dump<D>(p);
      // Never Zero unless all D+2 points lie in one hyperplane.
      const bool is_flat = all_in_one_hyperplane<D>(p);
      flat += is_flat;
      if ((got == Sign::Zero) != is_flat && budget.fail())
        ADD_FAILURE() << "insphere_perturbed<" << D << "> = " << sign_name(got) << " but the points are "
                      << (is_flat ? "" : "not ") << "in one hyperplane\n" << dump<D>(p);
      // inside_circumsphere of the first D+1, when they form a simplex.
      pr::Vertices<D + 1> s;
      std::copy(p.begin(), p.begin() + D + 1, s.begin());
      const int o = ref::orient(vecs<D>(s));
      if (o != 0) {
        const bool inside = pr::inside_circumsphere<D>(s, p[D + 1]);
        if (inside != (expected == o) && budget.fail())
          ADD_FAILURE() << "inside_circumsphere<" << D << "> = " << inside << ", reference says "
                        << (expected == o) << "\n" << dump<D>(p);
      }
    }
    EXPECT_EQ(budget.failures, 0) << "of " << cases << " cases";
    EXPECT_GT(unperturbed_zero, cases / 10) << "the pool should be rich in cospherical sets";
    if (name.rfind("hyperplane", 0) == 0) EXPECT_GT(flat, cases / 50);
  }
}

TYPED_TEST(Perturbation, EqualsUnperturbedWhenThatIsNonZero) {
  constexpr int D = TypeParam::value;
  Rng rng(0x9e770002 + D);
  FailureBudget budget;
  for (int n = 0; n < 3000; ++n) {
    std::array<Point<D>, D + 2> pts;
    for (auto& x : pts) x = n % 2 ? random_point<D>(rng) : grid_point<D>(rng, -2, 2);
    pr::Vertices<D + 2> p;
    for (int i = 0; i < D + 2; ++i) p[i] = {pts[i].data(), static_cast<uint32_t>(uniform_int(rng, 0, 1000000))};
    const Sign plain = pr::insphere<D>(coords_of(p));
    if (plain == Sign::Zero) continue;
    const Sign got = pr::insphere_perturbed<D>(p);
    if (got != plain && budget.fail())
      ADD_FAILURE() << "insphere_perturbed<" << D << "> = " << sign_name(got) << " but insphere = "
                    << sign_name(plain) << "\n" << dump<D>(p);
  }
  EXPECT_EQ(budget.failures, 0);
}

// Swapping two arguments (ids travel with the points) negates the answer; copying the coordinates
// elsewhere and permuting memory never changes it.
TYPED_TEST(Perturbation, AntisymmetricAndIndependentOfAddresses) {
  constexpr int D = TypeParam::value;
  Rng rng(0x9e770003 + D);
  for (auto& [name, points] : degenerate_pools<D>()) {
    SCOPED_TRACE(name);
    const Pool<D> pool(points, rng);
    FailureBudget budget;
    for (int n = 0; n < 1500; ++n) {
      const auto p = pool.template pick<D + 2>(rng);
      const Sign got = pr::insphere_perturbed<D>(p);

      auto swapped = p;
      const int i = uniform_int(rng, 0, D + 1);
      int j = uniform_int(rng, 0, D);
      if (j >= i) ++j;
      std::swap(swapped[i], swapped[j]);
      const Sign s = pr::insphere_perturbed<D>(swapped);
      if (s != -got && budget.fail())
        ADD_FAILURE() << "swapping arguments " << i << " and " << j << " gave " << sign_name(s) << " after "
                      << sign_name(got) << "\n" << dump<D>(p);

      // Copies in reverse memory order, same ids.
      std::vector<Point<D>> copies(D + 2);
      auto moved = p;
      for (int k = 0; k < D + 2; ++k) {
        std::copy(p[k].x, p[k].x + D, copies[D + 1 - k].begin());
        moved[k].x = copies[D + 1 - k].data();
      }
      const Sign m = pr::insphere_perturbed<D>(moved);
      if (m != got && budget.fail())
        ADD_FAILURE() << "copied coordinates gave " << sign_name(m) << " instead of " << sign_name(got) << "\n"
                      << dump<D>(p);
    }
    EXPECT_EQ(budget.failures, 0);
  }
}

// The identity of perturbation.h: if the query point has the least id and the unperturbed test is
// zero, the answer is "inside", i.e. orient(p_0..p_D).
TYPED_TEST(Perturbation, LeastIdQueryPointIsInside) {
  constexpr int D = TypeParam::value;
  Rng rng(0x9e770004 + D);
  const auto sphere = integer_sphere<D>(D == 2 ? 25 : D == 3 ? 9 : 4);
  const Pool<D> pool(sphere, rng);
  int checked = 0;
  for (int n = 0; n < 1000; ++n) {
    auto p = pool.template pick<D + 2>(rng);
    const auto least = std::min_element(p.begin(), p.end(), [](auto& a, auto& b) { return a.id < b.id; });
    std::swap(*least, p[D + 1]);
    pr::Vertices<D + 1> s;
    std::copy(p.begin(), p.begin() + D + 1, s.begin());
    const Sign o = pr::orient<D>(coords_of(s));
    if (o == Sign::Zero) continue;
    ++checked;
    ASSERT_EQ(pr::insphere_perturbed<D>(p), o) << dump<D>(p);
    ASSERT_TRUE(pr::inside_circumsphere<D>(s, p[D + 1])) << dump<D>(p);
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
