// sheets_without() (core/src/edit/sheets.h): the hole a deleted vertex leaves in a facet is filled
// with the facet's own CDT of the hole. Holes of a few vertices are cut into ears and flipped, larger
// ones take the star CDT of their projection; both must give a triangulation of the hole polygon
// whose every inner edge is locally Delaunay in the facet's plane. Checked here without the code
// under test: the fill's edges against the polygon's (each side once, each diagonal once each way),
// the orientation of every triangle, and the in-circle test in the plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "edit/sheets.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"
#include "sweepcdt/triangulation.h"

using namespace sweepcdt;
using predicates::Sign;

namespace {

// Random star-shaped polygons about the origin, in the plane z = x (oblique: its projection on
// the axes distorts circles, so the fill must be flipped to the in-plane CDT), each fanned from the
// origin: the facet triangles through vertex 0.
struct Fan {
  std::vector<double> points;  // 0: the vertex deleted; 1..n: the polygon, by angle about it
  std::vector<std::array<uint32_t, 3>> through_v;
  const double* point(uint32_t v) const { return points.data() + 3 * std::size_t{v}; }
};

Fan random_fan(std::mt19937_64& rng, int n) {
  // Angles from the centre anywhere below a half turn apart, and radii from 1 to 40: deep notches,
  // where a convex corner's triangle can hold other vertices (not an ear).
  std::uniform_real_distribution<double> angle_step(0.05, 1.0), radius(1.0, 40.0);
  std::vector<double> angles{0};
  double scale = 0;
  do {
    angles.assign(1, 0);
    for (int i = 1; i < n; ++i) angles.push_back(angles.back() + angle_step(rng));
    scale = 2 * std::numbers::pi / (angles.back() + angle_step(rng));
  } while (scale * (2 * std::numbers::pi / scale - angles.back()) >= 0.95 * std::numbers::pi ||
           [&] {
             for (int i = 1; i < n; ++i)
               if (scale * (angles[i] - angles[i - 1]) >= 0.95 * std::numbers::pi) return true;
             return false;
           }());
  Fan fan;
  fan.points = {0, 0, 0};
  for (double a : angles) {
    const double r = radius(rng), x = std::round(64 * r * std::cos(a * scale)) / 64, y = std::round(64 * r * std::sin(a * scale)) / 64;
    fan.points.insert(fan.points.end(), {x, y, x});
  }
  for (uint32_t i = 1; i <= static_cast<uint32_t>(n); ++i) fan.through_v.push_back({0, i, i % n + 1});
  return fan;
}

// The fill is a triangulation of polygon 1..n oriented like the fan, locally Delaunay in its plane.
void expect_cdt_of_hole(const Fan& fan, const std::vector<std::array<uint32_t, 3>>& fill, int n, const std::string& what) {
  ASSERT_EQ(fill.size(), static_cast<std::size_t>(n - 2)) << what;
  const auto projected = [&](uint32_t a, uint32_t b, uint32_t c) {  // drop z: the plane z = x projects one-to-one
    return predicates::orient<2>({fan.point(a), fan.point(b), fan.point(c)});
  };
  const Sign want = projected(fan.through_v[0][0], fan.through_v[0][1], fan.through_v[0][2]);
  std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> edges;  // directed edge -> apex
  for (const auto& t : fill) {
    EXPECT_EQ(projected(t[0], t[1], t[2]), want) << what << ": a triangle turned over or flat";
    for (int i = 0; i < 3; ++i) edges[{t[i], t[(i + 1) % 3]}].push_back(t[(i + 2) % 3]);
  }
  for (const auto& [edge, apexes] : edges) {
    ASSERT_EQ(apexes.size(), 1u) << what << ": edge " << edge.first << " " << edge.second << " twice the same way";
    const bool side = edge.second == edge.first % n + 1;  // a side of the polygon, the fan's way round
    if (side) continue;
    const auto back = edges.find({edge.second, edge.first});
    ASSERT_NE(back, edges.end()) << what << ": " << edge.first << " " << edge.second << " is neither a side nor a diagonal";
    // In-circle in the plane: the insphere test with a point off it (above the plane z = x).
    const double off[3] = {0, 1, -1};
    const uint32_t x = edge.first, y = edge.second, p = apexes[0], q = back->second[0];
    const predicates::Vertices<4> s{{{fan.point(x), x}, {fan.point(y), y}, {fan.point(p), p}, {off, kNone - 1}}};
    EXPECT_FALSE(predicates::inside_circumsphere<3>(s, {fan.point(q), q})) << what << ": diagonal " << x << " " << y << " not Delaunay";
  }
  for (uint32_t i = 1; i <= static_cast<uint32_t>(n); ++i)
    EXPECT_TRUE(edges.count({i, i % n + 1}) || edges.count({i % n + 1, i})) << what << ": side " << i << " missing";
}

}  // namespace

TEST(Sheets, HoleIsFilledWithItsCdt) {
  std::mt19937_64 rng(8);
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 4 + trial % 14;  // 4..17 vertices: ears (up to 12) and the star CDT beyond
    const Fan fan = random_fan(rng, n);
    const auto point = [&](uint32_t v) { return fan.point(v); };
    const auto order = [](uint32_t v) { return v; };
    const auto same_facet = [](uint32_t, uint32_t) { return true; };
    const auto sheets = detail::sheets_without<3>(0, fan.through_v, point, order, same_facet);
    ASSERT_EQ(sheets.size(), 1u) << "trial " << trial;
    expect_cdt_of_hole(fan, sheets[0].fill, n, "trial " + std::to_string(trial) + " (" + std::to_string(n) + " vertices)");
  }
}
