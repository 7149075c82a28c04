// The fold-point search of the verification (core/src/verify/split_of_two.h) against the search it
// replaced, kept here as the oracle: every pair of candidates tried with the exact test. They must
// give the same answer for every point and candidate set: the Steiner points of meshes cdt() makes
// (CAD parts, one with fold points), each against the points of every facet whose box holds it, as
// the verification asks of a fold point; and made-up sets on an inclined plane, with split points
// at every distance from their ends, nudged by one ulp, and on lines near the direction where the
// search's keys wrap around (only these catch a window too narrow, a missing wrap-around, or near
// points left out).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "sweepcdt/cdt.h"
#include "sweepcdt/io/read.h"
#include "sweepcdt/io/surface_arrays.h"
#include "sweepcdt/steiner_point.h"
#include "sweepcdt/verify_cdt.h"
#include "box_tree.h"
#include "verify/problems.h"
#include "verify/split_of_two.h"
#include "verify/surface_facets.h"
#include "verify/surface_points.h"

namespace sweepcdt::detail {
namespace {

// The exhaustive search (what surface_points.cpp ran before split_of_two.h).
bool oracle(std::span<const double> points, uint32_t s, const std::vector<uint32_t>& candidates) {
  const auto p = [&](uint32_t v) { return points.data() + 3 * std::size_t{v}; };
  const double* x = p(s);
  for (std::size_t i = 0; i < candidates.size(); ++i)
    for (std::size_t j = i + 1; j < candidates.size(); ++j) {
      const double* a = p(candidates[i]);
      const double* b = p(candidates[j]);
      bool inside = true;
      for (int c = 0; c < 3 && inside; ++c) inside = std::min(a[c], b[c]) <= x[c] && x[c] <= std::max(a[c], b[c]);
      if (inside && is_point_on_segment(a, b, x)) return true;
    }
  return false;
}

struct Tally {
  std::size_t cases = 0, splits = 0, fold_points = 0;
};

// Every Steiner point of the mesh against the points placed before it on every facet whose box
// holds it: the questions locate_points() asks of its fold points, and more (it asks only about
// points on no ridge); and the facets locate_points() put each fold point on are those.
void compare_on_mesh(const Plc<3>& input, const Triangulation<3>& tri, FacetMode mode, Tally& tally, const std::string& what) {
  MeshVerification v;
  Problems problems(v);
  const SurfaceFacets facets = group_surface_facets(input, mode);
  const SurfacePoints located = locate_points(input, facets, tri.points, problems);
  ASSERT_FALSE(problems.any()) << what << ": " << v.problems.front();
  std::vector<bool> on_ridge(tri.num_points(), false);
  for (const auto& line : located.on_edge)
    for (uint32_t w : line) on_ridge[w] = true;
  std::vector<Box<3>> boxes;
  for (uint32_t f = 0; f < facets.num_facets(); ++f) {
    std::vector<const double*> corners;
    for (uint32_t j : facets.triangles[f])
      for (int i = 0; i < 3; ++i) corners.push_back(input.point(input.simplex(j)[i]));
    boxes.push_back(Box<3>::of_points(corners.data(), static_cast<int>(corners.size())));
  }
  const BoxTree<3> facet_tree(std::move(boxes));
  for (uint32_t s = tri.num_input_points; s < tri.num_points(); ++s) {
    if (!on_ridge[s]) ++tally.fold_points;
    const double* x = tri.point(s);
    std::vector<uint32_t> split_on;  // the facets of which s splits two points, by the oracle
    facet_tree.for_each_overlap({{x[0], x[1], x[2]}, {x[0], x[1], x[2]}}, [&](uint32_t f) {
      std::vector<uint32_t> before;
      for (uint32_t w : located.on_facet[f])
        if (w < s) before.push_back(w);
      const bool expected = oracle(tri.points, s, before);
      EXPECT_EQ(is_split_of_two(tri.points, s, before), expected) << what << ": Steiner point " << s << " " << point_text(x) << ", facet " << f;
      ++tally.cases;
      tally.splits += expected;
      if (expected) split_on.push_back(f);
    });
    // locate_points() tries the points nearest s first (surface_points.cpp), then all of them.
    std::sort(split_on.begin(), split_on.end());
    if (!on_ridge[s]) EXPECT_EQ(located.facets_of[s], split_on) << what << ": fold point " << s;
  }
}

io::Soup jittered(io::Soup soup, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t i = 0; i < soup.points.size(); ++i) lo[i % 3] = std::min(lo[i % 3], soup.points[i]), hi[i % 3] = std::max(hi[i % 3], soup.points[i]);
  const double size = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) * 1e-12;
  for (double& x : soup.points) x += u(rng) * size;
  return soup;
}

// Points that a mesh made with --facets triangles has on input edges inside coplanar facets, fold
// points when checked as coplanar (flange_std.stl: 338); a CAD part jittered so that no face is
// flat; in the shared data, femur.off jittered (2 fold points that refine split, among 1166
// Steiner points), and thingi_1706459.stl, whose folds refine.cpp had to split before shell radii
// were rounded to 20 bits (its 10555 Steiner points now all lie on ridges: each is still asked
// about every facet whose box holds it).
TEST(VerifySplitOfTwo, AgreesWithEveryPairOnMeshesWithFoldPoints) {
  struct Case {
    std::string file;
    bool jitter;
    FacetMode made, checked;
  };
  const std::string cad = std::string(SWEEPCDT_TEST_DATA) + "/cad/";
  std::vector<Case> cases{{cad + "flange_std.stl", false, FacetMode::Triangles, FacetMode::Coplanar},
                          {cad + "rotated_box_std.obj", true, FacetMode::Coplanar, FacetMode::Coplanar}};
  const std::string shared = std::string(SWEEPCDT_SHARED_DATA) + "/";
  if (std::filesystem::exists(shared + "MANIFEST.md")) {
    cases.push_back({shared + "off/femur.off", true, FacetMode::Coplanar, FacetMode::Coplanar});
    cases.push_back({shared + "stl_binary/thingi_1706459.stl", false, FacetMode::Coplanar, FacetMode::Coplanar});
  }
  Tally tally;
  for (const Case& c : cases) {
    const io::Soup soup = io::read_soup(c.file);
    const Plc<3> input = io::plc_of_soup(c.jitter ? jittered(soup, 7) : soup);
    Options options;
    options.steiner = SteinerMode::Auto;
    options.facets = c.made;
    const Triangulation<3> tri = cdt(input, options);
    const std::string what = std::filesystem::path(c.file).filename().string() + (c.jitter ? " jittered" : "");
    Tally mine;
    compare_on_mesh(input, tri, c.checked, mine, what);
    std::printf("%s: %zu Steiner points, %zu fold points; %zu searches, %zu found\n", what.c_str(), tri.num_points() - tri.num_input_points,
                mine.fold_points, mine.cases, mine.splits);
    tally.cases += mine.cases, tally.splits += mine.splits, tally.fold_points += mine.fold_points;
  }
  EXPECT_GT(tally.fold_points, 0u);
  EXPECT_GT(tally.splits, 0u);
  EXPECT_LT(tally.splits, tally.cases);  // facets whose box holds a point that is not on them
}

// Made-up candidate sets on the plane z = (1 - x - y) / 1024 (inclined, so every coordinate
// rounds; flat enough that the search looks at it along z), each with points split from two of them
// at t from 2^-40 to 1 - 2^-40 (split points near one end, which the search tries against every
// candidate), some nudged by one ulp (they no longer split), and some between two points whose y
// differ by one ulp: seen from the split point their lines are nearly horizontal, one above and one
// below, so their keys lie near 0 and near 2, where the circle of keys wraps around.
TEST(VerifySplitOfTwo, AgreesWithEveryPairOnMadeUpSets) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> unit(0, 1);
  std::size_t cases = 0, splits = 0;
  for (int round = 0; round < 300; ++round) {
    const int k = 2 + round % 40;
    std::vector<double> points;
    const auto add = [&](double x, double y) { points.insert(points.end(), {x, y, (1 - x - y) / 1024}); };
    for (int c = 0; c < k; ++c) add(unit(rng) * 3 - 1, unit(rng) * 3 - 1);
    add(points[0] + 0.5 + unit(rng), std::nextafter(points[1], round % 2 ? 9.0 : -9.0));  // point k: y one ulp from point 0's
    std::vector<uint32_t> candidates(points.size() / 3);
    for (uint32_t c = 0; c < candidates.size(); ++c) candidates[c] = c;
    for (int q = 0; q < 20; ++q) {
      uint32_t a = static_cast<uint32_t>(rng() % candidates.size()), b = static_cast<uint32_t>(rng() % candidates.size());
      if (q < 4) a = 0, b = static_cast<uint32_t>(k);
      const double t = q % 5 == 0   ? std::ldexp(1.0, -static_cast<int>(1 + rng() % 40))
                       : q % 5 == 1 ? 1 - std::ldexp(1.0, -static_cast<int>(1 + rng() % 40))
                                    : unit(rng);
      double x[3];
      point_on_segment(points.data() + 3 * a, points.data() + 3 * b, t, x);
      if (q % 3 == 2) {
        const int c = static_cast<int>(rng() % 3);
        x[c] = std::nextafter(x[c], q % 2 ? 9.0 : -9.0);
      }
      std::vector<double> with_x = points;
      with_x.insert(with_x.end(), x, x + 3);
      const uint32_t s = static_cast<uint32_t>(candidates.size());
      const bool expected = oracle(with_x, s, candidates);
      ASSERT_EQ(is_split_of_two(with_x, s, candidates), expected)
          << "round " << round << ", split " << q << " of " << a << " and " << b << " at t = " << t << ": " << point_text(x);
      ++cases;
      splits += expected;
    }
  }
  std::printf("%zu made-up searches, %zu found\n", cases, splits);
  EXPECT_GT(splits, cases / 4);
  EXPECT_LT(splits, cases);
}

}  // namespace
}  // namespace sweepcdt::detail
