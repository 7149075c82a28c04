// compare_circumcenters, compare_power and compare_power_tuples (paper §3 keys, §6 perturbation)
// against perturbed circumspheres solved in rationals, plus their consistency with the perturbed
// insphere and the sides of a shared facet (Theorems 1 and 2).
#include <limits>
#include <set>

#include "predicate_test_util.h"

namespace {

using namespace sweepcdt::testutil;
namespace ref = sweepcdt::ref;
using pr::Sign;

template <int D>
std::vector<Point<D>> key_pool() {
  // Small grids: many equal circumcentre coordinates, cospherical and coplanar subsets.
  return D <= 3 ? grid_box<D>(-2, 2) : grid_box<D>(-1, 1);
}

template <int D>
bool degenerate(const pr::Vertices<D + 1>& s) {
  return ref::orient(vecs<D>(s)) == 0;
}

template <int D>
bool same_vertex_set(const pr::Vertices<D + 1>& s, const pr::Vertices<D + 1>& t) {
  std::set<uint32_t> a, b;
  for (const auto& v : s) a.insert(v.id);
  for (const auto& v : t) b.insert(v.id);
  return a == b;
}

// The perturbed circumsphere of s, with eps from the ranks of the ids in `eps`.
template <int D>
ref::LiftedSphere sphere(const pr::Vertices<D + 1>& s, const ref::EpsTable* eps) {
  ref::Vec e;
  for (const auto& v : s) e.push_back(eps ? (*eps)(v.id) : ref::Q(0));
  return *ref::lifted_sphere(vecs<D>(s), e);
}

// A non-degenerate simplex from the pool.
template <int D>
pr::Vertices<D + 1> random_simplex(const Pool<D>& pool, Rng& rng) {
  while (true) {
    auto s = pool.template pick<D + 1>(rng);
    if (!degenerate<D>(s)) return s;
  }
}

// A non-degenerate simplex sharing a random number (0..D+1) of vertices with s, in random order.
template <int D>
pr::Vertices<D + 1> neighbour_simplex(const Pool<D>& pool, const pr::Vertices<D + 1>& s, Rng& rng) {
  while (true) {
    auto t = s;
    const int replace = uniform_int(rng, 0, D + 1);
    for (int r = 0; r < replace; ++r) {
      const int slot = uniform_int(rng, 0, D);
      pr::Vertex v;
      do {
        v = pool.vertex(std::uniform_int_distribution<std::size_t>(0, pool.size() - 1)(rng));
      } while (std::any_of(t.begin(), t.end(), [&](const pr::Vertex& w) { return w.id == v.id; }));
      t[slot] = v;
    }
    std::shuffle(t.begin(), t.end(), rng);
    if (!degenerate<D>(t)) return t;
  }
}

template <int D>
std::string dump_pair(const pr::Vertices<D + 1>& s, const pr::Vertices<D + 1>& t) {
  return "s:\n" + dump<D>(s) + "t:\n" + dump<D>(t);
}

template <class T>
class SweepKeys : public ::testing::Test {};
TYPED_TEST_SUITE(SweepKeys, Dim2to5, DimName);

TYPED_TEST(SweepKeys, PerturbedKeysMatchReferenceOnGrid) {
  constexpr int D = TypeParam::value;
  Rng rng(0x6e750001 + D);
  const Pool<D> pool(key_pool<D>(), rng);
  FailureBudget budget;
  int ties = 0, power_ties = 0;
  const int cases = D <= 3 ? 2500 : 1000;
  for (int n = 0; n < cases; ++n) {
    const auto s = random_simplex<D>(pool, rng);
    const auto t = neighbour_simplex<D>(pool, s, rng);
    const auto delta = random_simplex<D>(pool, rng);
    auto all_ids = ids_of(s);
    for (uint32_t id : ids_of(t)) all_ids.push_back(id);
    const ref::EpsTable eps(all_ids);
    const auto ss = sphere<D>(s, &eps), st = sphere<D>(t, &eps);
    const auto us = sphere<D>(s, nullptr), ut = sphere<D>(t, nullptr);
    const bool same = same_vertex_set<D>(s, t);

    // Circumcentres, lexicographically.
    const int ec = ref::lex_compare(ss.center, st.center);
    ties += ref::lex_compare(us.center, ut.center) == 0 || us.center[0] == ut.center[0];
    const Sign gc = pr::compare_circumcenters<D>(s, t);
    if (pr::to_int(gc) != ec && budget.fail())
      ADD_FAILURE() << "compare_circumcenters<" << D << "> expected " << sign_name(ec) << ", got " << sign_name(gc)
                    << "\n" << dump_pair<D>(s, t);
    if (pr::compare_circumcenters<D>(t, s) != -gc && budget.fail())
      ADD_FAILURE() << "compare_circumcenters<" << D << "> not antisymmetric\n" << dump_pair<D>(s, t);
    if ((gc == Sign::Zero) != same && budget.fail())
      ADD_FAILURE() << "compare_circumcenters<" << D << "> = " << sign_name(gc) << " for "
                    << (same ? "the same" : "different") << " vertex sets\n" << dump_pair<D>(s, t);

    // Powers with respect to each seed vertex, and the tuple.
    int et = 0;
    for (int j = 0; j <= D; ++j) {
      const ref::Vec q = vec<D>(delta[j].x);
      const int ep = ref::sign(ref::power(ss, q) - ref::power(st, q));
      power_ties += ref::power(us, q) == ref::power(ut, q);
      if (et == 0) et = ep;
      const Sign gp = pr::compare_power<D>(s, t, delta[j]);
      if (pr::to_int(gp) != ep && budget.fail())
        ADD_FAILURE() << "compare_power<" << D << "> expected " << sign_name(ep) << ", got " << sign_name(gp)
                      << "\n" << dump_pair<D>(s, t) << dump_point<D>("q", delta[j].x);
    }
    const Sign gt = pr::compare_power_tuples<D>(s, t, delta);
    if (pr::to_int(gt) != et && budget.fail())
      ADD_FAILURE() << "compare_power_tuples<" << D << "> expected " << sign_name(et) << ", got " << sign_name(gt)
                    << "\n" << dump_pair<D>(s, t) << "delta:\n" << dump<D>(delta);
    if (pr::compare_power_tuples<D>(t, s, delta) != -gt && budget.fail())
      ADD_FAILURE() << "compare_power_tuples<" << D << "> not antisymmetric\n" << dump_pair<D>(s, t);
    if ((gt == Sign::Zero) != same && budget.fail())
      ADD_FAILURE() << "compare_power_tuples<" << D << "> = " << sign_name(gt) << " for "
                    << (same ? "the same" : "different") << " vertex sets\n" << dump_pair<D>(s, t)
                    << "delta:\n" << dump<D>(delta);
  }
  EXPECT_EQ(budget.failures, 0) << "of " << cases << " cases";
  EXPECT_GT(ties, cases / 20) << "too few unperturbed ties: the perturbation is not exercised";
  EXPECT_GT(power_ties, cases / 20);
}

// The star sweep's order (compare_power_sequences) where it matters most: the centre p on an edge ab
// that both simplices share (a deleted Steiner point on the segment it merges), so that their powers
// at p tie exactly, perturbation included, and the tie-breaking points q_k decide — mostly by the
// keys' enclosures, else exactly. Against the perturbed spheres in rationals; with and without the
// caches a sweep keeps per queue item (PowerSequenceCache).
TYPED_TEST(SweepKeys, StarOrderPastATieAtTheCentreMatchesReference) {
  constexpr int D = TypeParam::value;
  Rng rng(0x6e750007 + D);
  const Pool<D> pool(key_pool<D>(), rng);
  FailureBudget budget;
  int decided_later = 0, cached = 0;
  const int cases = D <= 3 ? 1500 : 600;
  for (int n = 0; n < cases; ++n) {
    // s = {a, b, ...} and t = {a, b, ...} sharing 2..D of their vertices.
    auto s = random_simplex<D>(pool, rng);
    pr::Vertices<D + 1> t;
    do {
      t = s;
      for (int slot = 2; slot <= D; ++slot)
        if (uniform_int(rng, 0, 1) == 1 || slot == D) {
          pr::Vertex v;
          do v = pool.vertex(std::uniform_int_distribution<std::size_t>(0, pool.size() - 1)(rng));
          while (std::any_of(t.begin(), t.end(), [&](const pr::Vertex& w) { return w.id == v.id; }));
          t[slot] = v;
        }
    } while (degenerate<D>(t));
    // The centre halfway along ab, then the tie-breaking points as star_sweep_cdt makes them: the
    // centre with one coordinate changed; q_1 is sometimes a point the centre moves away from.
    std::array<Point<D>, D + 2> points;
    for (int k = 0; k < D; ++k) points[0][k] = (s[0].x[k] + s[1].x[k]) / 2;
    for (int k = 2; k < D + 2; ++k) {
      points[k] = points[0];
      points[k][k - 2] = points[0][k - 2] == 0 ? 1 : -points[0][k - 2];
    }
    std::array<int8_t, D + 2> toward;
    toward.fill(1);
    points[1] = points[2];
    if (uniform_int(rng, 0, 1) == 1) {
      points[1] = pool.pts[std::uniform_int_distribution<std::size_t>(0, pool.size() - 1)(rng)];
      toward[1] = -1;
    }
    std::array<pr::Vertex, D + 2> delta;
    for (int k = 0; k < D + 2; ++k) delta[k] = {points[k].data(), std::numeric_limits<uint32_t>::max()};
    std::shuffle(s.begin(), s.end(), rng);
    std::shuffle(t.begin(), t.end(), rng);

    auto all_ids = ids_of(s);
    for (uint32_t id : ids_of(t)) all_ids.push_back(id);
    const ref::EpsTable eps(all_ids);
    const auto ss = sphere<D>(s, &eps), st = sphere<D>(t, &eps);
    int expected = 0;
    for (int k = 0; k < D + 2 && expected == 0; ++k) {
      const ref::Vec q = vec<D>(points[k].data());
      expected = toward[k] * ref::sign(ref::power(ss, q) - ref::power(st, q));
      decided_later += k == 1 && expected != 0;
    }
    const Sign got = pr::compare_power_sequences<D>(s, t, delta.data(), toward.data(), D + 2);
    if (pr::to_int(got) != expected && budget.fail())
      ADD_FAILURE() << "compare_power_sequences<" << D << "> expected " << sign_name(expected) << ", got " << sign_name(got)
                    << "\n" << dump_pair<D>(s, t) << dump<D>(delta);
    if (pr::compare_power_sequences<D>(t, s, delta.data(), toward.data(), D + 2) != -got && budget.fail())
      ADD_FAILURE() << "compare_power_sequences<" << D << "> not antisymmetric\n" << dump_pair<D>(s, t);
    // With each simplex's cache (a sweep's queue item): the same answers, the second time from what
    // the first worked out.
    pr::PowerSequenceCache s_cache, t_cache;
    for (int again = 0; again < 2; ++again) {
      if (pr::compare_power_sequences<D>(s, t, delta.data(), toward.data(), D + 2, &s_cache, &t_cache) != got && budget.fail())
        ADD_FAILURE() << "compare_power_sequences<" << D << "> with caches (call " << again << ") differs\n" << dump_pair<D>(s, t);
      if (pr::compare_power_sequences<D>(t, s, delta.data(), toward.data(), D + 2, &t_cache, &s_cache) != -got && budget.fail())
        ADD_FAILURE() << "compare_power_sequences<" << D << "> with caches not antisymmetric\n" << dump_pair<D>(s, t);
    }
    cached += (s_cache.known & 2) != 0 && (t_cache.known & 2) != 0;
  }
  EXPECT_EQ(budget.failures, 0) << "of " << cases << " cases";
  EXPECT_GT(decided_later, cases / 2) << "too few ties at the centre: the case is not exercised";
  // (In 2D two simplices through ab share that facet: decided across it, without enclosures.)
  if constexpr (D > 2) EXPECT_GT(cached, cases / 3) << "the enclosures at q_1 were not kept in the caches";
}

// q need not be a vertex; q a vertex of s or t, or of both, is the interesting case.
TYPED_TEST(SweepKeys, PowerAtVerticesAndArbitraryPoints) {
  constexpr int D = TypeParam::value;
  Rng rng(0x6e750002 + D);
  const Pool<D> pool(key_pool<D>(), rng);
  FailureBudget budget;
  for (int n = 0; n < (D <= 3 ? 1500 : 700); ++n) {
    const auto s = random_simplex<D>(pool, rng);
    const auto t = neighbour_simplex<D>(pool, s, rng);
    auto all_ids = ids_of(s);
    for (uint32_t id : ids_of(t)) all_ids.push_back(id);
    const ref::EpsTable eps(all_ids);
    const auto ss = sphere<D>(s, &eps), st = sphere<D>(t, &eps);
    const Point<D> free_point = grid_point<D>(rng, -3, 3);
    const pr::Vertex candidates[] = {s[uniform_int(rng, 0, D)], t[uniform_int(rng, 0, D)],
                                     {free_point.data(), 999999}};
    for (const pr::Vertex& q : candidates) {
      const ref::Vec qv = vec<D>(q.x);
      const int ep = ref::sign(ref::power(ss, qv) - ref::power(st, qv));
      const Sign gp = pr::compare_power<D>(s, t, q);
      if (pr::to_int(gp) != ep && budget.fail())
        ADD_FAILURE() << "compare_power<" << D << "> expected " << sign_name(ep) << ", got " << sign_name(gp)
                      << "\n" << dump_pair<D>(s, t) << dump_point<D>("q", q.x);
      if (pr::compare_power<D>(t, s, q) != -gp && budget.fail())
        ADD_FAILURE() << "compare_power<" << D << "> not antisymmetric\n" << dump_pair<D>(s, t);
    }
    EXPECT_EQ(pr::compare_power<D>(s, s, candidates[2]), Sign::Zero);
    EXPECT_EQ(pr::compare_circumcenters<D>(s, s), Sign::Zero);
  }
  EXPECT_EQ(budget.failures, 0);
}

// Random doubles: wherever the unperturbed reference difference is non-zero, it decides.
TYPED_TEST(SweepKeys, UnperturbedRandomDoubles) {
  constexpr int D = TypeParam::value;
  Rng rng(0x6e750003 + D);
  FailureBudget budget;
  int decided = 0;
  const int cases = 1500;
  for (int n = 0; n < cases; ++n) {
    std::vector<Point<D>> pts(2 * D + 3);
    for (auto& p : pts) p = random_point<D>(rng);
    pr::Vertices<D + 1> s, t, delta;
    for (int i = 0; i <= D; ++i) {
      s[i] = {pts[i].data(), static_cast<uint32_t>(i)};
      delta[i] = {pts[D + 2 + i].data(), static_cast<uint32_t>(D + 2 + i)};
      t[i] = s[i];
    }
    // For even n, t shares the facet s_1..s_D with s (the sweep's typical pair); for odd n, nothing.
    t[0] = {pts[D + 1].data(), static_cast<uint32_t>(D + 1)};
    if (n % 2)
      for (int i = 1; i <= D; ++i) t[i] = {pts[D + 2 + i].data(), static_cast<uint32_t>(D + 2 + i)};
    const auto us = sphere<D>(s, nullptr), ut = sphere<D>(t, nullptr);
    if (const int e = ref::sign(us.center[0] - ut.center[0]); e != 0) {
      ++decided;
      const Sign g = pr::compare_circumcenters<D>(s, t);
      if (pr::to_int(g) != e && budget.fail())
        ADD_FAILURE() << "compare_circumcenters<" << D << "> expected " << sign_name(e) << ", got " << sign_name(g)
                      << "\n" << dump_pair<D>(s, t);
    }
    const ref::Vec q0 = vec<D>(delta[0].x);
    if (const int e = ref::sign(ref::power(us, q0) - ref::power(ut, q0)); e != 0) {
      const Sign g = pr::compare_power<D>(s, t, delta[0]);
      const Sign gt = pr::compare_power_tuples<D>(s, t, delta);
      if ((pr::to_int(g) != e || pr::to_int(gt) != e) && budget.fail())
        ADD_FAILURE() << "compare_power<" << D << "> expected " << sign_name(e) << ", got " << sign_name(g)
                      << " (tuple " << sign_name(gt) << ")\n" << dump_pair<D>(s, t) << "delta:\n" << dump<D>(delta);
    }
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(decided, cases * 9 / 10);
}

// The certified enclosures the sweeps order their queues by (power_interval: the hand-written
// filters in D = 3, 4, the generic ones in D = 2, 5; circumcenter_interval) contain the exact keys, on
// random doubles, on near-degenerate sets (grid points moved by a few ulps) and at large and small
// scales, and are finite (informative) on most of them.
TYPED_TEST(SweepKeys, KeyIntervalsEncloseTheExactKeys) {
  constexpr int D = TypeParam::value;
  Rng rng(0x1e7e0000 + D);
  FailureBudget budget;
  int finite = 0;
  const int cases = 1200;
  const double scales[] = {1.0, 0x1p-40, 0x1p30, 1e-3, 0x1p-300};
  for (int n = 0; n < cases; ++n) {
    std::array<Point<D>, D + 2> pts;
    const double scale = scales[n % std::size(scales)];
    for (auto& p : pts) {
      p = n % 2 ? random_point<D>(rng) : grid_point<D>(rng, -3, 3);
      for (int k = 0; k < D; ++k) {
        p[k] *= scale;
        if (n % 2 == 0)
          for (int u = uniform_int(rng, 0, 3); u > 0; --u) p[k] = std::nextafter(p[k], uniform_int(rng, 0, 1) ? 1e300 : -1e300);
      }
    }
    pr::Vertices<D + 1> s;
    for (int i = 0; i <= D; ++i) s[i] = {pts[i].data(), static_cast<uint32_t>(i)};
    if (degenerate<D>(s)) continue;
    const auto exact = sphere<D>(s, nullptr);
    const ref::Q power = ref::power(exact, vec<D>(pts[D + 1].data()));
    const pr::KeyInterval p = pr::power_interval<D>(s, pts[D + 1].data());
    const pr::KeyInterval c = pr::circumcenter_interval<D>(s, 0);
    finite += std::isfinite(p.lo) && std::isfinite(p.hi);
    const bool in_p = (p.lo == -INFINITY || ref::Q(p.lo) <= power) && (p.hi == INFINITY || power <= ref::Q(p.hi));
    const bool in_c = (c.lo == -INFINITY || ref::Q(c.lo) <= exact.center[0]) && (c.hi == INFINITY || exact.center[0] <= ref::Q(c.hi));
    if ((!in_p || !in_c) && budget.fail())
      ADD_FAILURE() << "key interval<" << D << "> misses the exact key: power [" << p.lo << ", " << p.hi << "] exact "
                    << power.get_d() << ", centre [" << c.lo << ", " << c.hi << "] exact " << exact.center[0].get_d() << "\n"
                    << dump<D>(pr::coords_of(s));
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(finite, cases * 7 / 10);
}

// The double-word powers the star sweep caches per queue item (power_words) order two simplices
// exactly as the rational powers do whenever they certify an order, certify none when the powers
// are equal, and certify most orders that the enclosures leave open, on grid points moved by a few
// ulps (nearly cospherical and coplanar, as the stars of points on facets bent by rounding) at
// several scales, with the point a free point, a vertex of one simplex or of both.
TYPED_TEST(SweepKeys, PowerWordsOrderAsTheExactPowers) {
  constexpr int D = TypeParam::value;
  Rng rng(0x70770000 + D);
  FailureBudget budget;
  int open = 0, certified_open = 0, equal = 0;
  const int cases = 3000;
  const double scales[] = {1.0, 0x1p-40, 0x1p30, 1e-3};
  for (int n = 0; n < cases; ++n) {
    std::array<Point<D>, 2 * D + 3> pts;
    const double scale = scales[n % std::size(scales)];
    for (auto& p : pts) {
      p = grid_point<D>(rng, -2, 2);
      for (int k = 0; k < D; ++k) {
        p[k] *= scale;
        if (n % 3)
          for (int u = uniform_int(rng, 0, 3); u > 0; --u) p[k] = std::nextafter(p[k], uniform_int(rng, 0, 1) ? 1e300 : -1e300);
      }
    }
    pr::Vertices<D + 1> s, t;
    for (int i = 0; i <= D; ++i) s[i] = {pts[i].data(), static_cast<uint32_t>(i)};
    t = s;
    for (int r = uniform_int(rng, 1, D + 1), i = 0; i < r; ++i)  // t shares D + 1 - r vertices with s
      t[i] = {pts[D + 1 + i].data(), static_cast<uint32_t>(D + 1 + i)};
    std::shuffle(t.begin(), t.end(), rng);
    if (degenerate<D>(s) || degenerate<D>(t)) continue;
    const int which = n % 4;  // a free point, a vertex of s, of t, of both when they share one
    const double* q = which == 0 ? pts[2 * D + 2].data() : which == 1 ? s[0].x : which == 2 ? t[0].x : s[D].x;
    const ref::Vec qv = vec<D>(q);
    const int expected = ref::sign(ref::power(sphere<D>(s, nullptr), qv) - ref::power(sphere<D>(t, nullptr), qv));
    const std::optional<Sign> got = pr::power_order_from_words(pr::power_words<D>(s, q), pr::power_words<D>(t, q));
    const pr::KeyInterval a = pr::power_interval<D>(s, q), b = pr::power_interval<D>(t, q);
    const bool apart = a.hi < b.lo || b.hi < a.lo;
    if (expected == 0) ++equal;
    if (expected != 0 && !apart) ++open, certified_open += got.has_value();
    if (got && pr::to_int(*got) != expected && budget.fail())
      ADD_FAILURE() << "power words<" << D << "> certified " << sign_name(pr::to_int(*got)) << ", exact "
                    << sign_name(expected) << "\n" << dump_pair<D>(s, t) << dump_point<D>("q", q);
  }
  EXPECT_EQ(budget.failures, 0);
  EXPECT_GT(equal, cases / 20) << "too few equal powers: the zero case is not exercised";
  EXPECT_GT(open, cases / 50) << "too few orders the enclosures leave open";
  EXPECT_GT(certified_open, open / 2) << "the words certify too few of the orders the enclosures leave open (the rest are second order in the ulps)";
}

// Theorems 1 and 2 on grid (degenerate) inputs: for s1 = f + a and s2 = f + b with a, b strictly on
// opposite sides of f, if the pair is locally Delaunay under the perturbation (b not inside the
// circumsphere of s1), the simplex behind f comes first, by circumcentre (sweep plane) and by power
// tuple (sweep sphere); if it is not, the one in front comes first.
TYPED_TEST(SweepKeys, BehindFacetComesFirstWhenLocallyDelaunay) {
  constexpr int D = TypeParam::value;
  Rng rng(0x6e750004 + D);
  const Pool<D> pool(key_pool<D>(), rng);
  FailureBudget budget;
  int delaunay = 0, checked = 0;
  while (checked < (D <= 3 ? 2500 : 1200)) {
    const auto picked = pool.template pick<D + 2>(rng);
    pr::Coords<D> f;
    for (int i = 0; i < D; ++i) f[i] = picked[i].x;
    const pr::Vertex a = picked[D], b = picked[D + 1];
    pr::Vertices<D + 1> s1, s2;
    for (int i = 0; i < D; ++i) s1[i] = s2[i] = picked[i];
    s1[D] = a;
    s2[D] = b;
    const int oa = ref::orient(vecs<D>(s1)), ob = ref::orient(vecs<D>(s2));
    if (oa == 0 || ob == 0 || oa == ob) continue;
    ++checked;
    const auto delta = random_simplex<D>(pool, rng);
    const pr::SphereSweep<D> sphere_sweep{coords_of(delta)};

    const bool b_inside = pr::inside_circumsphere<D>(s1, b);
    if (pr::inside_circumsphere<D>(s2, a) != b_inside && budget.fail())
      ADD_FAILURE() << "inside_circumsphere is not symmetric across the facet\n" << dump_pair<D>(s1, s2);
    delaunay += !b_inside;
    const Sign want = b_inside ? Sign::Positive : Sign::Negative;  // sign of compare(behind, front)

    const pr::Side plane_side = pr::side_of<D>(pr::PlaneSweep{}, f, a.x);
    const auto& pb = plane_side == pr::Side::Behind ? s1 : s2;
    const auto& pf = plane_side == pr::Side::Behind ? s2 : s1;
    const Sign gc = pr::compare_circumcenters<D>(pb, pf);
    if (gc != want && budget.fail())
      ADD_FAILURE() << "plane sweep: compare_circumcenters(behind, front) = " << sign_name(gc) << ", want "
                    << sign_name(want) << (b_inside ? " (not locally Delaunay)" : " (locally Delaunay)") << "\nbehind:\n"
                    << dump<D>(pb) << "front:\n" << dump<D>(pf);

    const pr::Side sphere_side = pr::side_of<D>(sphere_sweep, f, a.x);
    const auto& sb = sphere_side == pr::Side::Behind ? s1 : s2;
    const auto& sf = sphere_side == pr::Side::Behind ? s2 : s1;
    const Sign gp = pr::compare_power_tuples<D>(sb, sf, delta);
    if (gp != want && budget.fail())
      ADD_FAILURE() << "sphere sweep: compare_power_tuples(behind, front) = " << sign_name(gp) << ", want "
                    << sign_name(want) << "\nbehind:\n" << dump<D>(sb) << "front:\n" << dump<D>(sf) << "delta:\n"
                    << dump<D>(delta);
  }
  EXPECT_EQ(budget.failures, 0) << "of " << checked << " facet pairs";
  EXPECT_GT(delaunay, checked / 10);
  EXPECT_LT(delaunay, checked * 9 / 10);
}

}  // namespace
