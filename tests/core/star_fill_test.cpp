// check_star_fill() (edit/star_fill.h), which vertex deletion runs instead of validate() on a star's
// new simplices, against validate() itself: on star-shaped polytopes in D = 2..4 (links of vertices
// in random and grid Delaunay triangulations, radially scaled convex polytopes, some with inner
// constraints) and on triangulations of them that are right and wrong in every way the checks name
// (the star sweep's, with a simplex dropped, doubled, turned over or moved to another vertex, fans
// from each vertex, an interior facet made a constraint or a notated one). The two must agree on
// every one, and both kinds of verdict must occur.
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <random>
#include <string>

#include "edit/star_fill.h"
#include "star_shapes.h"
#include "sweep/sweep_cdt.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/validate.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

struct Verdicts {
  int accepted = 0, rejected = 0;
  std::map<std::string, int> failed;  // check_star_fill()'s rejections by check
};

template <int D>
void expect_same_verdict(Triangulation<D> fill, const Plc<D>& polytope, const std::string& what, Verdicts& verdicts) {
  Triangulation<D> reference = fill;
  compute_neighbors(reference);
  const ValidationReport report = validate(reference, polytope);
  const bool valid = report.ok();
  const std::string failure = detail::check_star_fill(fill, polytope);
  EXPECT_EQ(failure.empty(), valid) << what << ": " << (valid ? failure : "validate() rejects it, check_star_fill() accepts it: " + report.summary());
  if (failure.empty() && valid) EXPECT_EQ(fill.neighbors, reference.neighbors) << what;
  ++(valid ? verdicts.accepted : verdicts.rejected);
  if (!failure.empty()) ++verdicts.failed[failure.substr(0, failure.find(':'))];
}

// Right and wrong triangulations were both met, and wrong ones failed every kind of check.
void expect_both_verdicts(const Verdicts& verdicts) {
  EXPECT_GT(verdicts.accepted, 0) << "nothing right was checked: the test proves little";
  for (const char* check : {"orientation", "facet-multiplicity", "interior-facet-sides", "domain-boundary", "constraints", "locally-delaunay"})
    EXPECT_GT(verdicts.failed.count(check), 0u) << "no triangulation failed " << check << ": the test proves little there";
}

// Simplex t of `fill` positively oriented (two vertices swapped if not); false when it is flat.
template <int D>
bool make_positive(Triangulation<D>& fill, std::size_t t) {
  predicates::Coords<D + 1> c;
  for (int i = 0; i <= D; ++i) c[i] = fill.point(fill.simplices[t * (D + 1) + i]);
  const predicates::Sign sign = predicates::orient<D>(c);
  if (sign == predicates::Sign::Negative) std::swap(fill.simplices[t * (D + 1)], fill.simplices[t * (D + 1) + 1]);
  return sign != predicates::Sign::Zero;
}

// The fan from vertex w: a simplex on every boundary facet without w (flat ones left out).
template <int D>
Triangulation<D> fan_from(const Plc<D>& polytope, uint32_t w) {
  Triangulation<D> fan;
  fan.points = polytope.points;
  fan.num_input_points = polytope.num_points();
  for (uint32_t j = 0; j < polytope.num_simplices(); ++j) {
    if (polytope.exterior_of(j) == ExteriorSide::None || std::count(polytope.simplex(j), polytope.simplex(j) + D, w)) continue;
    fan.simplices.insert(fan.simplices.end(), polytope.simplex(j), polytope.simplex(j) + D);
    fan.simplices.push_back(w);
    if (!make_positive(fan, fan.num_simplices() - 1)) fan.simplices.resize(fan.simplices.size() - (D + 1));
  }
  return fan;
}

// An interior facet of `fill` (one of two simplices), if any.
template <int D>
std::optional<std::array<uint32_t, D>> interior_facet(const Triangulation<D>& fill, std::mt19937_64& rng) {
  Triangulation<D> with = fill;
  compute_neighbors(with);
  std::vector<std::size_t> inner;
  for (std::size_t k = 0; k < with.neighbors.size(); ++k)
    if (with.neighbors[k] != kNone) inner.push_back(k);
  if (inner.empty()) return std::nullopt;
  const std::size_t k = inner[rng() % inner.size()];
  std::array<uint32_t, D> f;
  for (int i = 0, j = 0; i <= D; ++i)
    if (i != static_cast<int>(k % (D + 1))) f[j++] = fill.simplices[k - k % (D + 1) + i];
  return f;
}

// The star sweep's triangulation of `polytope` (as vertex deletion runs it: a failure reported, not
// thrown), and wrong or other ones made from it.
template <int D>
void compare_on(const Plc<D>& polytope, const std::array<double, D>& centre, std::mt19937_64& rng, const std::string& what,
                Verdicts& verdicts) {
  CdtStatistics stats;
  std::optional<NoCdtError> failed;
  Triangulation<D> swept;
  try {
    swept = detail::star_sweep_cdt<D>(polytope, centre, Options{}, stats, false, nullptr, &failed);
  } catch (const NoCdtError&) {
    failed.emplace("thrown", std::vector<uint32_t>{});
  }
  for (uint32_t w = 0; w < polytope.num_points(); ++w) expect_same_verdict(fan_from(polytope, w), polytope, what + " fan from " + std::to_string(w), verdicts);
  if (failed) return;
  expect_same_verdict(swept, polytope, what + " swept", verdicts);
  const std::size_t n = swept.num_simplices();
  if (n == 0) return;
  const std::size_t t = rng() % n;
  Triangulation<D> dropped = swept;
  dropped.simplices.erase(dropped.simplices.begin() + t * (D + 1), dropped.simplices.begin() + (t + 1) * (D + 1));
  expect_same_verdict(dropped, polytope, what + " one simplex dropped", verdicts);
  Triangulation<D> doubled = swept;
  doubled.simplices.insert(doubled.simplices.end(), swept.simplex(t), swept.simplex(t) + D + 1);
  expect_same_verdict(doubled, polytope, what + " one simplex doubled", verdicts);
  Triangulation<D> turned = swept;
  std::swap(turned.simplices[t * (D + 1)], turned.simplices[t * (D + 1) + 1]);
  expect_same_verdict(turned, polytope, what + " one simplex turned over", verdicts);
  Triangulation<D> moved = swept;
  moved.simplices[t * (D + 1) + rng() % (D + 1)] = static_cast<uint32_t>(rng() % polytope.num_points());
  if (make_positive(moved, t)) expect_same_verdict(moved, polytope, what + " one vertex moved", verdicts);
  // An interior facet of the fill made a constraint: unnotated (an inner facet: right, and no longer
  // tested for the Delaunay property), notated (wrong: a simplex on its exterior side); and the
  // triangulations above against the polytope with that inner constraint.
  if (const auto f = interior_facet(swept, rng)) {
    for (const ExteriorSide side : {ExteriorSide::None, ExteriorSide::Positive}) {
      Plc<D> inner = polytope;
      inner.simplices.insert(inner.simplices.end(), f->begin(), f->end());
      inner.exterior.push_back(side);
      const std::string with = what + (side == ExteriorSide::None ? " with an inner constraint" : " with a notated inner facet");
      expect_same_verdict(swept, inner, with + ", swept", verdicts);
      expect_same_verdict(moved, inner, with + ", one vertex moved", verdicts);
      for (uint32_t w = 0; w < polytope.num_points(); ++w) expect_same_verdict(fan_from(inner, w), inner, with + ", fan from " + std::to_string(w), verdicts);
    }
  }
}

template <int D>
void links_of_vertices(int count, int grid, int seeds, int per_seed) {
  Verdicts verdicts;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(500 * D + seed);
    Plc<D> points;
    points.points = fixtures::distinct_grid_points<D>(rng, count, grid ? grid : D <= 3 ? 1 << 20 : 1 << 6);
    const Triangulation<D> tri = cdt(points);
    for (uint32_t v = 0, tried = 0; v < points.num_points() && tried < static_cast<uint32_t>(per_seed); ++v) {
      if (!fixtures::is_interior_vertex(tri, v)) continue;
      ++tried;
      std::array<double, D> centre;
      std::copy_n(tri.point(v), D, centre.begin());
      compare_on<D>(fixtures::link_polytope(tri, v), centre, rng, "seed " + std::to_string(seed) + " link of " + std::to_string(v), verdicts);
    }
  }
  expect_both_verdicts(verdicts);
}

template <int D>
void radial_polytopes(int count, int max_scale, int seeds) {
  Verdicts verdicts;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(91 * D + seed);
    compare_on<D>(fixtures::radial_polytope<D>(rng, count, max_scale), std::array<double, D>{}, rng, "radial seed " + std::to_string(seed),
                  verdicts);
  }
  expect_both_verdicts(verdicts);
}

}  // namespace

TEST(StarFill, AgreesWithValidateOnLinksOfRandomVertices2) { links_of_vertices<2>(40, 0, 3, 20); }
TEST(StarFill, AgreesWithValidateOnLinksOfRandomVertices3) { links_of_vertices<3>(50, 0, 3, 20); }
TEST(StarFill, AgreesWithValidateOnLinksOfRandomVertices4) { links_of_vertices<4>(30, 0, 2, 4); }
TEST(StarFill, AgreesWithValidateOnLinksOfGridVertices3) { links_of_vertices<3>(27, 3, 4, 10); }
TEST(StarFill, AgreesWithValidateOnRadialPolytopes3) { radial_polytopes<3>(24, 3, 30); }
TEST(StarFill, AgreesWithValidateOnConvexPolytopesWithTies3) { radial_polytopes<3>(20, 1, 20); }
