// The 4D filters' two bounds (filters4.h) against the exact determinant: |value - exact| <= error,
// for the column sums' bound (the first stage, orientation.cpp) and the permanent's, on random,
// nearly degenerate and wide-ranging inputs; and the column sums' bound is never the tighter one.
// The sign tests (orient_insphere_test.cpp) check the stages together; this one checks each bound
// on its own, where nearly degenerate inputs bring the error closest to it.
#include <cmath>

#include "filters4.h"
#include "predicate_test_util.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
namespace detail = sweepcdt::predicates::detail;

// The worst |value - exact| / error seen, as a double (rationals: the comparison itself is exact).
struct WorstRatio {
  double worst = 0.0;
  int cases = 0, failures = 0;
  void check(const detail::Estimate& e, const ref::Q& exact, const char* what) {
    ++cases;
    const ref::Q error = abs(ref::Q(e.value) - exact);
    if (std::isinf(e.error)) return;  // not admitted: the exact stage decides
    if (error > ref::Q(e.error) && failures++ < 5) ADD_FAILURE() << what << ": error " << error.get_d() << " above the bound " << e.error;
    if (e.error > 0) worst = std::max(worst, error.get_d() / e.error);
  }
};

// Points of one of the kinds below, in E^4.
std::array<Point<4>, 6> points(Rng& rng, int kind) {
  std::array<Point<4>, 6> p;
  if (kind == 0) {  // random
    for (auto& x : p) x = random_point<4>(rng);
  } else if (kind == 1) {  // the last two rounded affine combinations of the first four, nudged
    for (int i = 0; i < 4; ++i) p[i] = random_point<4>(rng);
    for (int i = 4; i < 6; ++i)
      for (int k = 0; k < 4; ++k) {
        double x = p[0][k];
        for (int j = 1; j < 4; ++j) x += uniform(rng, -1, 1) * (p[j][k] - p[0][k]);
        p[i][k] = nudge(x, uniform_int(rng, -2, 2));
      }
  } else if (kind == 2) {  // nearly cospherical: rounded points of a sphere, nudged
    const Point<4> centre = random_point<4>(rng);
    for (auto& x : p) {
      Point<4> g;
      double len2 = 0;
      for (double& gk : g) len2 += (gk = std::normal_distribution<double>()(rng)) * gk;
      for (int k = 0; k < 4; ++k) x[k] = nudge(centre[k] + g[k] / std::sqrt(len2), uniform_int(rng, -1, 1));
    }
  } else {  // coordinates of very different magnitudes in one simplex, and tiny ones
    const double scale = std::ldexp(1.0, uniform_int(rng, -1040, 60));
    for (auto& x : p)
      for (double& c : x) c = uniform(rng) * (uniform_int(rng, 0, 3) == 0 ? std::ldexp(scale, -uniform_int(rng, 0, 80)) : scale);
  }
  return p;
}

TEST(FilterBounds, FourDimensionalBoundsHoldAndColumnSumsAreNeverTighter) {
  Rng rng(0xb0d4);
  WorstRatio orient_sums, orient_permanent, insphere_sums, insphere_permanent;
  int looser = 0, decided_by_sums = 0;
  for (int n = 0; n < 8000; ++n) {
    const auto p = points(rng, n % 4);
    sweepcdt::predicates::Coords<6> all;
    for (int i = 0; i < 6; ++i) all[i] = p[i].data();
    sweepcdt::predicates::Coords<5> simplex;
    std::copy(all.begin(), all.begin() + 5, simplex.begin());
    // The exact determinants, as filters4.h defines them.
    ref::Mat o(4, ref::Vec(4)), s(5, ref::Vec(5));
    for (int i = 0; i < 5; ++i) {
      ref::Q lift = 0;
      for (int k = 0; k < 4; ++k) {
        if (i < 4) o[i][k] = ref::Q(p[i][k]) - ref::Q(p[4][k]);
        s[i][k] = ref::Q(p[i][k]) - ref::Q(p[5][k]);
        lift += s[i][k] * s[i][k];
      }
      s[i][4] = lift;
    }
    const ref::Q exact_orient = ref::det(o), exact_insphere = ref::det(s);
    const detail::Orient4Filter orient(simplex);
    const detail::Insphere4Filter insphere(all);
    const detail::Estimate os = orient.column_sums(), op = orient.permanent();
    const detail::Estimate is = insphere.column_sums(), ip = insphere.permanent();
    orient_sums.check(os, exact_orient, "orient4, column sums");
    orient_permanent.check(op, exact_orient, "orient4, permanent");
    insphere_sums.check(is, exact_insphere, "insphere4, column sums");
    insphere_permanent.check(ip, exact_insphere, "insphere4, permanent");
    EXPECT_EQ(os.value, op.value);  // one expansion, two bounds
    EXPECT_EQ(is.value, ip.value);
    looser += !(os.error >= op.error) + !(is.error >= ip.error);
    decided_by_sums += std::fabs(is.value) > is.error;
  }
  EXPECT_EQ(looser, 0) << "a column sums' bound below the permanent's";
  // The nearly degenerate kinds must come close to a bound, or the test could not see one too small.
  EXPECT_GT(std::max(orient_permanent.worst, insphere_permanent.worst), 1e-3);
  // The first stage must decide most random and nearly cospherical cases, or it is only a cost.
  EXPECT_GT(decided_by_sums, 8000 / 4);
  std::printf("[ bounds ] worst error / bound: orient4 %.3g (column sums) %.3g (permanent), insphere4 %.3g %.3g; "
              "the column sums decided %d of %d insphere signs\n",
              orient_sums.worst, orient_permanent.worst, insphere_sums.worst, insphere_permanent.worst, decided_by_sums, 8000);
}

}  // namespace
