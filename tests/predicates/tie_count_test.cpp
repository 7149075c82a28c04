// perturbation_ties_on_this_thread() (stats.h): what cdt() reads to decide whether another
// perturbation order (paper §6) could change a failed run. It must count ties of cospherical points
// — insphere and sweep keys — but not keys that tie for other reasons, and only the calling thread's.
#include <gtest/gtest.h>

#include <functional>
#include <thread>

#include "sweepcdt/predicates/perturbation.h"
#include "sweepcdt/predicates/stats.h"
#include "sweepcdt/predicates/sweep_keys.h"

namespace {

namespace pr = sweepcdt::predicates;

// The unit cube's corners (cospherical), and a point off their sphere.
const double kCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
const double kOff[3] = {0.5, 0.5, 3};

pr::Vertex corner(uint32_t i) { return {kCube[i], i}; }

uint64_t ties_during(const std::function<void()>& f) {
  const uint64_t before = pr::perturbation_ties_on_this_thread();
  f();
  return pr::perturbation_ties_on_this_thread() - before;
}

TEST(TieCount, InsphereCountsCosphericalTiesOnly) {
  EXPECT_EQ(ties_during([] { pr::insphere_perturbed<3>({corner(0), corner(1), corner(2), corner(4), corner(7)}); }), 1u);
  EXPECT_EQ(ties_during([] { pr::insphere_perturbed<3>({corner(0), corner(1), corner(2), corner(4), {kOff, 8}}); }), 0u);
}

TEST(TieCount, KeysCountOnlyWhenTheSimplicesShareASphere) {
  // Two tetrahedra of the cube: one circumsphere, equal centres and powers everywhere.
  const pr::Vertices<4> s{corner(0), corner(1), corner(2), corner(4)}, t{corner(7), corner(6), corner(5), corner(3)};
  EXPECT_EQ(ties_during([&] { pr::compare_circumcenters<3>(s, t); }), 1u);
  EXPECT_EQ(ties_during([&] { pr::compare_power_tuples<3>(s, t, s); }), 1u);
  // A tetrahedron on s's face (0, 1, 2) with its apex above the face's circumcentre: its centre
  // shares x and y with s's (both on the axis of the face's circumcircle), z differs. The
  // perturbation breaks the tie in x, but the five points are not cospherical.
  const double apex[3] = {0.5, 0.5, 2};
  const pr::Vertices<4> u{corner(0), corner(1), corner(2), {apex, 8}};
  EXPECT_EQ(ties_during([&] { pr::compare_circumcenters<3>(s, u); }), 0u);
}

TEST(TieCount, PerThread) {
  uint64_t other = 0;
  const uint64_t here = ties_during([&] {
    std::thread worker([&] { other = ties_during([] { pr::insphere_perturbed<3>({corner(0), corner(1), corner(2), corner(4), corner(7)}); }); });
    worker.join();
  });
  EXPECT_EQ(other, 1u);
  EXPECT_EQ(here, 0u);
}

}  // namespace
