// Vertex deletion (EditableCdt, paper §5) against the CDT computed from scratch: after every
// deletion the CDT must equal cdt() of the PLC that is left (the CDT is unique under the §6
// perturbation) and pass validate(); deletions that are refused leave everything unchanged.
// Inputs in D = 2..5: points in a simplex whose facets are notated constraints (vertices inside,
// on the facets — where the facet is re-triangulated — and, for D = 3, on edges), the integer grid
// (exact ties everywhere), convex-hull domains (their hull vertices too, down to one simplex), and
// Steiner points of a PLC that has no CDT without them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <thread>

#include "brute_force_cdt.h"
#include "cad_noise.h"
#include "edit/blocked_segment.h"
#include "random_plc.h"
#include "simplex_tiling.h"
#include "star_shapes.h"
#include "sweepcdt/editable_cdt.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/validate.h"
#include "test_shapes.h"
#include "triangulation_util.h"

using namespace sweepcdt;

namespace {

// The boundary of the CDT of `points` (its hull faces) as notated constraints: a facet-bounded
// PLC with the same CDT.
template <int D>
Plc<D> hull_bounded(const std::vector<double>& points) {
  Plc<D> plc;
  plc.points = points;
  const Triangulation<D> hull = cdt(plc);
  for (std::size_t t = 0; t < hull.num_simplices(); ++t)
    for (int i = 0; i <= D; ++i) {
      if (hull.neighbors[t * (D + 1) + i] != kNone) continue;
      for (int k = 0; k <= D; ++k)
        if (k != i) plc.simplices.push_back(hull.simplex(t)[k]);
      plc.exterior.push_back((D - i) % 2 == 0 ? ExteriorSide::Negative : ExteriorSide::Positive);
    }
  return plc;
}

// Integer points of the simplex {x >= 0, sum x <= size}: its corners, then `count` at random. With
// `general`, only points inside it or inside its facets (on exactly one of its D + 1 hyperplanes),
// none on lower-dimensional faces.
template <int D>
std::vector<double> simplex_points(std::mt19937_64& rng, int count, int size, bool general = false) {
  std::set<std::vector<double>> seen;
  std::vector<double> points;
  const auto add = [&](const std::vector<double>& p) {
    if (seen.insert(p).second) points.insert(points.end(), p.begin(), p.end());
  };
  add(std::vector<double>(D, 0.0));
  for (int k = 0; k < D; ++k) {
    std::vector<double> corner(D, 0.0);
    corner[k] = size;
    add(corner);
  }
  std::uniform_int_distribution<int> coordinate(0, size);
  while (static_cast<int>(seen.size()) < count + D + 1) {
    std::vector<double> p(D);
    int sum = 0, on = 0;
    for (auto& x : p) {
      sum += static_cast<int>(x = coordinate(rng));
      on += x == 0;
    }
    on += sum == size;
    if (sum <= size && (!general || on <= 1)) add(p);
  }
  return points;
}

struct Tally {
  int deleted = 0, refused = 0, no_cdt = 0;
};

// Deletes vertices in random order, checking each result against cdt() from scratch, until no
// further deletion succeeds. Returns what happened.
template <int D>
Tally delete_all(const Plc<D>& plc, uint64_t seed, const std::string& what) {
  EditableCdt<D> mesh(plc, cdt(plc));
  std::vector<uint32_t> order(plc.num_points());
  for (uint32_t v = 0; v < order.size(); ++v) order[v] = v;
  std::mt19937_64 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  Tally tally;
  for (bool progress = true; progress;) {
    progress = false;
    for (uint32_t v : order) {
      if (!mesh.has_vertex(v)) continue;
      const auto before = mesh.snapshot();
      try {
        mesh.remove_vertex(v);
      } catch (const VertexRemovalError&) {
        ++tally.refused;
        EXPECT_EQ(fixtures::simplex_set(mesh.snapshot().triangulation), fixtures::simplex_set(before.triangulation)) << what;
        continue;
      } catch (const NoCdtError& e) {
        ++tally.no_cdt;
        EXPECT_EQ(fixtures::simplex_set(mesh.snapshot().triangulation), fixtures::simplex_set(before.triangulation)) << what;
        continue;
      }
      progress = true;
      ++tally.deleted;
      const auto now = mesh.snapshot();
      const auto report = validate(now.triangulation, now.plc);
      if (!report.ok()) {
        ADD_FAILURE() << what << " after deleting " << v << "\n" << report.summary();
        return tally;
      }
      Triangulation<D> reference;
      try {
        reference = cdt(now.plc);
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << " after deleting " << v << ": cdt() from scratch: " << e.what();
        return tally;
      }
      if (fixtures::simplex_set(now.triangulation) != fixtures::simplex_set(reference)) {
        ADD_FAILURE() << what << " after deleting " << v << ": not the CDT computed from scratch";
        return tally;
      }
    }
  }
  return tally;
}

template <int D>
void simplex_domain(int count, int size, int seeds) {
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(91 * D + seed);
    const Plc<D> plc = hull_bounded<D>(simplex_points<D>(rng, count, size, true));
    const std::string what = "D=" + std::to_string(D) + " simplex seed " + std::to_string(seed);
    const Tally tally = delete_all(plc, seed, what);
    EXPECT_GT(tally.deleted, count / 2) << what << ": " << tally.refused << " refused, " << tally.no_cdt << " without CDT";
  }
}

// Thin fins whose Steiner points the deletion pass mostly refuses early, every segment refined (the
// sweep plane: no lazy refinement) and the points kept: with CAD noise (points rounded off their
// segments, facets bent), or exact (noisy_fins' comb in binary fractions: points exactly on their
// segments; every triangle's edges segments, for more points). The CDT, its refined PLC in `refined`.
Triangulation<3> refined_fins(bool noise, Plc<3>& refined) {
  std::vector<double> xs{0, 1}, tops{0.1875};
  for (int fin = 0; fin < 3; ++fin) {
    xs.push_back(xs.back() + 0.015625);
    tops.push_back(1.0);
    xs.push_back(xs.back() + 0.1875);
    tops.push_back(0.1875 + 0.0078125 * fin);
  }
  const Plc<3> fins = noise ? sweepcdt::testing::noisy_fins(2) : fixtures::extruded_columns(xs, tops, 1.0);
  Options options = mesh_defaults();
  options.remove_steiner_points = false;
  options.algorithm = Algorithm::SweepPlane;
  if (!noise) options.facets = FacetMode::Triangles;
  return cdt(fins, options, &refined);
}

}  // namespace

// In D = 2 and 3 every vertex but the simplex's corners can go: the result is one simplex.
TEST(EditableCdt, DeleteDownToASimplex2) {
  std::mt19937_64 rng(3);
  const Plc<2> plc = hull_bounded<2>(simplex_points<2>(rng, 40, 16));
  const Tally tally = delete_all(plc, 3, "D=2");
  EXPECT_EQ(tally.deleted, static_cast<int>(plc.num_points()) - 3);
}
TEST(EditableCdt, DeleteDownToASimplex3) {
  for (int seed = 0; seed < 3; ++seed) {
    std::mt19937_64 rng(seed);
    const Plc<3> plc = hull_bounded<3>(simplex_points<3>(rng, 40, 8));
    const Tally tally = delete_all(plc, seed, "D=3 seed " + std::to_string(seed));
    EXPECT_EQ(tally.deleted, static_cast<int>(plc.num_points()) - 4) << "seed " << seed << ": " << tally.no_cdt << " without CDT";
  }
}
TEST(EditableCdt, SimplexDomain4) { simplex_domain<4>(24, 10, 2); }
TEST(EditableCdt, SimplexDomain5) { simplex_domain<5>(16, 10, 1); }

// The grid: cospherical ties everywhere, facets full of coplanar points.
TEST(EditableCdt, Grid2) {
  std::mt19937_64 rng(1);
  const Tally tally = delete_all(hull_bounded<2>(fixtures::distinct_grid_points<2>(rng, 25, 4)), 1, "D=2 grid");
  EXPECT_GT(tally.deleted, 10);
}
TEST(EditableCdt, Grid3) {
  std::mt19937_64 rng(2);
  const Tally tally = delete_all(hull_bounded<3>(fixtures::distinct_grid_points<3>(rng, 27, 2)), 2, "D=3 grid");
  EXPECT_GT(tally.deleted, 10);
}
TEST(EditableCdt, Grid4) {
  std::mt19937_64 rng(4);
  const Tally tally = delete_all(hull_bounded<4>(fixtures::distinct_grid_points<4>(rng, 40, 2)), 4, "D=4 grid");
  EXPECT_GT(tally.deleted, 2);  // most grid points lie on lower-dimensional faces of the box (refused in D = 4)
}

// Convex-hull domains: every vertex can go, those on the hull too (paper §5: the algorithm "works
// correctly even if v lies on the boundary of the CDT"); the hull shrinks down to one simplex.
template <int D>
void hull_domain(int count, int grid, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Plc<D> plc;
  plc.points = fixtures::distinct_grid_points<D>(rng, count, grid);
  const std::string what = "D=" + std::to_string(D) + " hull, grid " + std::to_string(grid);
  const Tally tally = delete_all(plc, seed, what);
  EXPECT_EQ(tally.deleted, count - (D + 1)) << what << ": " << tally.refused << " refused, " << tally.no_cdt << " without CDT";
}
TEST(EditableCdt, HullDomain2) { hull_domain<2>(60, 1 << 20, 8); }
TEST(EditableCdt, HullDomain3) { hull_domain<3>(60, 1 << 20, 9); }
TEST(EditableCdt, HullDomainGrid3) { hull_domain<3>(40, 3, 10); }
TEST(EditableCdt, HullDomain4) { hull_domain<4>(25, 1 << 6, 11); }

// Schönhardt's twisted prism has no CDT (no triangulation at all); with Steiner points it has one.
// Deleting them all cannot succeed: each deletion that fails must fail exactly when cdt() of the
// PLC left without that vertex finds no CDT (under vertex-id order: §6), and leave the mesh as it was.
TEST(EditableCdt, DeletionsThatLeaveNoCdt) {
  const Plc<3> prism = fixtures::twisted_prism(0.5);
  EXPECT_THROW(cdt(prism), NoCdtError);
  Options steiner;
  steiner.steiner = SteinerMode::Auto;
  Plc<3> refined;
  Triangulation<3> tri = cdt(prism, steiner, &refined);
  ASSERT_GT(tri.num_points(), prism.num_points());
  EditableCdt<3> mesh(refined, tri);
  int failed = 0, deleted = 0;
  for (uint32_t v = static_cast<uint32_t>(prism.num_points()); v < tri.num_points(); ++v) {
    Plc<3> left;
    try {
      left = mesh.plc_without(v);
    } catch (const VertexRemovalError&) {  // a rounded Steiner point off its segment: a corner
      EXPECT_THROW(mesh.remove_vertex(v), VertexRemovalError);
      continue;
    }
    bool has_cdt = true;
    try {
      has_cdt = cdt(left).perturbation_rank.empty();
    } catch (const NoCdtError&) {
      has_cdt = false;
    }
    const auto before = mesh.snapshot();
    try {
      mesh.remove_vertex(v);
      ++deleted;
      EXPECT_TRUE(has_cdt) << v;
      const auto now = mesh.snapshot();
      EXPECT_EQ(now.plc.simplices, left.simplices) << v;
      EXPECT_EQ(fixtures::simplex_set(now.triangulation), fixtures::simplex_set(cdt(left))) << v;
    } catch (const NoCdtError& e) {
      ++failed;
      EXPECT_FALSE(has_cdt) << v;
      // Refused without throwing, the deletion hands out the witness the exception carried: a
      // simplex of v's neighbours (the deletion pass tries v again only when one of them, or of
      // its constraint neighbours, goes).
      std::vector<uint32_t> neighbours, witness;
      EXPECT_FALSE(mesh.try_commit_removal(mesh.plan_removal(v), neighbours, &witness)) << v;
      EXPECT_EQ(witness, e.witness()) << v;
      EXPECT_EQ(witness.size(), 4u) << v;
      const std::vector<uint32_t> link = mesh.neighbours(v);
      for (uint32_t w : witness) EXPECT_TRUE(std::binary_search(link.begin(), link.end(), w)) << v << ": witness vertex " << w;
      // Its constraint neighbours: the other vertices of the PLC's facets through v, as the
      // snapshot's PLC has them (renumbered: old_ids).
      std::vector<uint32_t> on_facets;
      for (std::size_t j = 0; j < before.plc.num_simplices(); ++j) {
        const uint32_t* f = before.plc.simplex(j);
        if (std::none_of(f, f + 3, [&](uint32_t x) { return before.old_ids[x] == v; })) continue;
        for (int k = 0; k < 3; ++k)
          if (before.old_ids[f[k]] != v) on_facets.push_back(before.old_ids[f[k]]);
      }
      std::sort(on_facets.begin(), on_facets.end());
      on_facets.erase(std::unique(on_facets.begin(), on_facets.end()), on_facets.end());
      EXPECT_FALSE(on_facets.empty()) << v;
      EXPECT_EQ(mesh.constraint_neighbours(v), on_facets) << v;
      const auto after = mesh.snapshot();
      EXPECT_EQ(fixtures::simplex_set(after.triangulation), fixtures::simplex_set(before.triangulation));
      EXPECT_EQ(after.plc.simplices, before.plc.simplices);
    }
  }
  EXPECT_GT(failed, 0);
  const auto last = mesh.snapshot();
  EXPECT_TRUE(validate_triangulated(last.triangulation, last.plc).ok());
}

// The brute-force oracle (paper §1's definition, exact LP visibility) on small constrained PLCs with
// grid ties: for every vertex, a deletion succeeds exactly when the oracle's constrained Delaunay
// simplices of the PLC left triangulate it (vertex-id perturbation), and then equals them.
template <int D>
void against_brute_force(int inner, int outer, int constraints, int seeds) {
  int agreed = 0, refused = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(500 * D + seed);
    const Plc<D> plc = fixtures::random_constrained_plc<D>(rng, inner, outer, constraints);
    Triangulation<D> tri;
    try {
      tri = cdt(plc);
    } catch (const NoCdtError&) {
      continue;
    }
    if (!tri.perturbation_rank.empty()) continue;
    for (uint32_t v = 0; v < plc.num_points(); ++v) {
      EditableCdt<D> mesh(plc, tri);
      Plc<D> left;
      try {
        left = mesh.plc_without(v);
      } catch (const VertexRemovalError&) {
        continue;
      }
      const auto oracle = fixtures::brute_force_cdt<D>(left);
      const bool has_cdt = fixtures::tiling_report<D>(left, oracle.simplices).triangulation();
      const std::string what = "D=" + std::to_string(D) + " seed " + std::to_string(seed) + " vertex " + std::to_string(v);
      try {
        mesh.remove_vertex(v);
        EXPECT_TRUE(has_cdt) << what;
        EXPECT_EQ(fixtures::simplex_set(mesh.snapshot().triangulation), oracle.simplices) << what;
      } catch (const NoCdtError&) {
        EXPECT_FALSE(has_cdt) << what;
        ++refused;
      } catch (const VertexRemovalError& e) {
        ADD_FAILURE() << what << ": plc_without() accepted it, remove_vertex() refused: " << e.what();
      }
      ++agreed;
    }
  }
  EXPECT_GT(agreed, seeds) << "too few deletions compared";
  std::cout << "[ oracle ] D=" << D << ": " << agreed << " deletions compared, " << refused << " refused without a CDT\n";
}
TEST(EditableCdt, AgreesWithBruteForce2) { against_brute_force<2>(5, 4, 3, 30); }
TEST(EditableCdt, AgreesWithBruteForce3) { against_brute_force<3>(6, 4, 3, 60); }

// A constraining triangle split at the midpoint v of its edge ab (two constraints), among random
// grid points near that edge: v makes ab's halves Delaunay, and without v some of these PLCs have no
// CDT. Every deletion of v must agree with the brute-force oracle on the PLC left — refused exactly
// when it has none.
TEST(EditableCdt, DeletingASplitPointAgreesWithBruteForce) {
  int compared = 0, refused = 0;
  for (int seed = 0; seed < 300; ++seed) {
    std::mt19937_64 rng(7000 + seed);
    Plc<3> plc;
    plc.points = {0, 0, 0, 4, 0, 0, 2, 3, 0, 2, 0, 0};  // a, b, c, v
    plc.simplices = {0, 3, 2, 3, 1, 2};
    std::uniform_int_distribution<int> x(-1, 5), y(-2, 2), z(1, 2), sign(0, 1);
    for (int k = 0; k < 5; ++k) plc.points.insert(plc.points.end(), {double(x(rng)), double(y(rng)), double(sign(rng) ? z(rng) : -z(rng))});
    if (!find_problems(plc).empty()) continue;
    Triangulation<3> tri;
    try {
      tri = cdt(plc);
    } catch (const NoCdtError&) {
      continue;
    }
    if (!tri.perturbation_rank.empty()) continue;
    EditableCdt<3> mesh(plc, tri);
    const Plc<3> left = mesh.plc_without(3);
    const auto oracle = fixtures::brute_force_cdt<3>(left);
    const bool has_cdt = fixtures::tiling_report<3>(left, oracle.simplices).triangulation();
    ++compared;
    try {
      mesh.remove_vertex(3);
      EXPECT_TRUE(has_cdt) << "seed " << seed;
      EXPECT_EQ(fixtures::simplex_set(mesh.snapshot().triangulation), oracle.simplices) << "seed " << seed;
    } catch (const NoCdtError&) {
      ++refused;
      EXPECT_FALSE(has_cdt) << "seed " << seed;
    }
  }
  std::cout << "[ oracle ] " << compared << " split points deleted or refused, " << refused << " refused without a CDT\n";
  EXPECT_GT(compared, 100);
  EXPECT_GT(refused, 0) << "no PLC without a CDT: the refusal is not exercised";
}

// Re-triangulated facets are their own 2D CDTs, also in a plane oblique to every axis (where the
// projection the star CDT runs on distorts circles): every edge between two coplanar constraining
// triangles is locally Delaunay in their plane (the in-circle test as an insphere with a point off
// the plane). The tetrahedron's facet x + y + 2z = 24 holds many points; all are deleted in turn.
TEST(EditableCdt, ObliqueFacetsStayDelaunayInTheirPlane) {
  std::vector<double> points = {0, 0, 0, 24, 0, 0, 0, 24, 0, 0, 0, 12, 5, 5, 3, 9, 4, 2};
  std::mt19937_64 rng(21);
  std::uniform_int_distribution<int> coin(0, 2);
  for (int z = 1; z <= 10; ++z)
    for (int x = 1; x + 2 * z < 24; ++x)
      if (coin(rng) == 0) points.insert(points.end(), {double(x), double(24 - 2 * z - x), double(z)});
  const Plc<3> plc = hull_bounded<3>(points);
  EditableCdt<3> mesh(plc, cdt(plc));
  const auto in_plane_delaunay = [](const Plc<3>& now) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<std::pair<uint32_t, uint32_t>>> edges;  // -> (triangle, apex)
    for (uint32_t t = 0; t < now.num_simplices(); ++t)
      for (int i = 0; i < 3; ++i) {
        const uint32_t x = now.simplex(t)[(i + 1) % 3], y = now.simplex(t)[(i + 2) % 3];
        edges[{std::min(x, y), std::max(x, y)}].push_back({t, now.simplex(t)[i]});
      }
    int checked = 0;
    for (const auto& [edge, on] : edges) {
      if (on.size() != 2) continue;
      const double *x = now.point(edge.first), *y = now.point(edge.second), *p = now.point(on[0].second), *q = now.point(on[1].second);
      if (predicates::orient<3>({x, y, p, q}) != predicates::Sign::Zero) continue;  // not coplanar: a ridge of the box
      const double off[3] = {x[0] + 1, x[1] + 2, x[2] + 5};  // off every face of this simplex
      const predicates::Vertices<4> s{{{x, edge.first}, {y, edge.second}, {p, on[0].second}, {off, kNone - 1}}};
      if (predicates::inside_circumsphere<3>(s, {q, on[1].second})) return -1;
      ++checked;
    }
    return checked;
  };
  ASSERT_GT(in_plane_delaunay(plc), 0);
  int deleted = 0;
  for (uint32_t v = 0; v < plc.num_points(); ++v) {
    const double* p = plc.point(v);
    if (p[0] + p[1] + 2 * p[2] != 24 || p[0] == 0 || p[1] == 0 || p[2] == 0) continue;  // on the oblique facet only
    try {
      mesh.remove_vertex(v);
      ++deleted;
    } catch (const Error&) {
      continue;
    }
    const auto now = mesh.snapshot();
    ASSERT_GE(in_plane_delaunay(now.plc), 0) << "after deleting " << v;
    ASSERT_EQ(fixtures::simplex_set(now.triangulation), fixtures::simplex_set(cdt(now.plc))) << "after deleting " << v;
  }
  EXPECT_GT(deleted, 20);
}

// Steiner points that rounding put a few ulps off their segment or facet are corners of the refined
// PLC's bent facets: refused by default, deletable with unbend_facets_at_steiner_points() (what the
// deletion pass of cdt() asks for). Thin fins with CAD noise, refined and kept whole; every Steiner
// point is deleted in turn from two copies, one of each kind. The second must delete points the
// first refuses as corners, and after each of its deletions the CDT must be the one cdt() builds
// from scratch for the PLC left, its facets the input's pieces (each new triangle tagged with one
// input triangle, on the same side as before).
TEST(EditableCdt, SteinerPointsOffTheirSegmentGoWhenFacetsMayUnbend) {
  const Plc<3> fins = sweepcdt::testing::noisy_fins();
  Options options = mesh_defaults();
  options.remove_steiner_points = false;
  Plc<3> refined;
  const Triangulation<3> tri = cdt(fins, options, &refined);
  ASSERT_GT(tri.steiner_on.size(), 50u);
  ASSERT_EQ(refined.tags.size(), refined.num_simplices());  // the input triangle of each piece
  EditableCdt<3> straight(refined, tri), unbending(refined, tri);
  unbending.unbend_facets_at_steiner_points(1000);  // every star
  int corners_deleted = 0, deleted = 0;
  for (uint32_t v = tri.num_input_points; v < tri.num_points(); ++v) {
    bool corner = false;
    try {
      straight.remove_vertex(v);
    } catch (const VertexRemovalError&) {
      corner = true;
    } catch (const NoCdtError&) {
    }
    try {
      unbending.remove_vertex(v);
    } catch (const Error&) {
      continue;
    }
    corners_deleted += corner;
    if (++deleted % 8 != 0) continue;  // from scratch after every 8th (and, below, the last)
    const auto now = unbending.snapshot();
    ASSERT_EQ(fixtures::simplex_set(now.triangulation), fixtures::simplex_set(cdt(now.plc))) << "after deleting " << v;
  }
  const auto now = unbending.snapshot();
  ASSERT_EQ(fixtures::simplex_set(now.triangulation), fixtures::simplex_set(cdt(now.plc)));
  Triangulation<3> whole = now.triangulation;  // validated against the refined PLC, Steiner points as its own
  whole.num_input_points = static_cast<uint32_t>(now.plc.num_points());
  whole.steiner_on.clear();
  const ValidationReport report = validate(whole, now.plc);
  ASSERT_TRUE(report.ok()) << report.summary();
  // Each piece turns like its input triangle in the projection along the largest component of the
  // input's normal (what `sweepcdt check` tests: a piece folded over would fail it).
  for (std::size_t j = 0; j < now.plc.num_simplices(); ++j) {
    const auto* t = now.plc.simplex(j);
    const auto* in = fins.simplex(now.plc.tags[j]);
    const predicates::Coords<3> input{fins.point(in[0]), fins.point(in[1]), fins.point(in[2])};
    double n[3];
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, l = (k + 2) % 3;
      n[k] = (input[1][i] - input[0][i]) * (input[2][l] - input[0][l]) - (input[1][l] - input[0][l]) * (input[2][i] - input[0][i]);
    }
    const int drop = std::abs(n[0]) >= std::abs(n[1]) && std::abs(n[0]) >= std::abs(n[2]) ? 0 : std::abs(n[1]) >= std::abs(n[2]) ? 1 : 2;
    EXPECT_EQ(predicates::orient_projected<3>({now.plc.point(t[0]), now.plc.point(t[1]), now.plc.point(t[2])}, drop),
              predicates::orient_projected<3>(input, drop))
        << "piece " << j << " of input triangle " << now.plc.tags[j];
  }
  std::cout << "[ fins ] " << tri.steiner_on.size() << " Steiner points: " << deleted << " deleted, " << corners_deleted
            << " of them corners of bent facets (refused without unbending)\n";
  EXPECT_GT(corners_deleted, 10);
}

// While unbending (the deletion pass), a Steiner point on a segment whose merged pieces would not be
// Delaunay among its star's vertices is refused before its cavity is built (blocked_segment.h). Each
// such early refusal must be right: cdt() from scratch of the PLC the deletion would leave finds no
// CDT either. Thin fins, with CAD noise (points rounded off their segments, facets bent: without the
// test that a point's pieces are flat, this seed fails) and exact (binary fractions: points on their
// segments; every fourth refusal checked), every Steiner point tried in turn, the others deleted
// meanwhile, so the stars grow as the pass makes them grow.
TEST(EditableCdt, EarlyRefusalsOfMergedSegmentsAgreeWithCdtFromScratch) {
  for (const bool noise : {true, false}) {
    Plc<3> refined;
    const Triangulation<3> tri = refined_fins(noise, refined);
    ASSERT_GT(tri.steiner_on.size(), 20u);
    EditableCdt<3> mesh(refined, tri);
    mesh.unbend_facets_at_steiner_points(1000);
    int early = 0, checked = 0, deleted = 0, later = 0;
    Options whole;
    whole.algorithm = Algorithm::CavitySweep;  // decides exactly whether the PLC left has a CDT
    for (int pass = 0; pass < 2; ++pass)
      for (uint32_t v = tri.num_input_points; v < tri.num_points(); ++v) {
        if (!mesh.has_vertex(v)) continue;
        Plc<3> left;
        try {
          left = mesh.plc_without(v);
        } catch (const VertexRemovalError&) {
          continue;
        }
        try {
          mesh.remove_vertex(v);
          ++deleted;
        } catch (const NoCdtError& e) {
          if (std::string(e.what()).find("is not Delaunay (every sphere") == std::string::npos) {
            ++later;
            continue;
          }
          if (++early % (noise ? 1 : 4) != 0) continue;  // each check is a cdt() of the whole
          ++checked;
          EXPECT_THROW(cdt(left, whole), NoCdtError) << (noise ? "noisy" : "exact") << " fins, vertex " << v << ": " << e.what();
        }
      }
    std::cout << "[ fins ] " << (noise ? "noisy" : "exact") << ": " << tri.steiner_on.size() << " Steiner points, " << deleted
              << " deleted, " << early << " refused early (" << checked << " checked), " << later << " refused by the star sweep\n";
    EXPECT_GT(early, 10);
    EXPECT_GT(deleted, 10);
  }
}

// An early refusal's witness: the merged segment's ends and three vertices of the star, one of which
// every sphere through those ends holds. While those five stay, the refusal stands (deletions only
// add vertices to v's star, never take one away but the deleted one; with guessed refusals on, as in
// the deletion pass, a point whose pieces a deletion bent is refused by the same test as a guess),
// which is why the deletion pass need not try v again when another neighbour goes
// (remove_steiner.cpp). Every Steiner point of the fins tried in turn, the others deleted meanwhile;
// after each deletion every refusal whose witness is intact is tried again and must still be
// refused early.
TEST(EditableCdt, EarlyRefusalsStandWhileTheirWitnessStays) {
  for (const bool noise : {true, false}) {
    Plc<3> refined;
    const Triangulation<3> tri = refined_fins(noise, refined);
    const std::vector<uint32_t>& rank = tri.perturbation_rank;
    EditableCdt<3> mesh(refined, tri);
    mesh.unbend_facets_at_steiner_points(1000);
    mesh.guess_blocked_refusals(true);  // as the deletion pass: guessed refusals have no witness
    const auto early = [](const NoCdtError& e) { return std::string(e.what()).find("is not Delaunay (every sphere") != std::string::npos; };
    const auto guessed = [](const VertexRemovalError& e) { return std::string(e.what()).find("lies off that segment or its facets are bent") != std::string::npos; };
    std::map<uint32_t, std::vector<uint32_t>> standing;  // refused early: vertex -> witness
    int refusals = 0, retried = 0, deleted = 0;
    for (int pass = 0; pass < 2; ++pass)
      for (uint32_t v = tri.num_input_points; v < tri.num_points(); ++v) {
        if (!mesh.has_vertex(v) || standing.contains(v)) continue;
        try {
          mesh.remove_vertex(v);
        } catch (const NoCdtError& e) {
          if (!early(e)) continue;
          ++refusals;
          std::vector<uint32_t> witness = e.witness();
          ASSERT_EQ(witness.size(), 5u) << "vertex " << v;
          for (const uint32_t w : witness) EXPECT_TRUE(mesh.has_vertex(w) && w != v) << "vertex " << v << ": witness " << w;
          // What the witness says, checked on its own: every sphere through its first two holds one of the others.
          const auto vertex = [&](uint32_t w) { return predicates::Vertex{refined.point(w), rank.empty() ? w : rank[w]}; };
          EXPECT_EQ(detail::segment_in_spheres(vertex(witness[0]), vertex(witness[1]), {vertex(witness[2]), vertex(witness[3]), vertex(witness[4])}).answer,
                    detail::SegmentInSpheres::Blocked)
              << "vertex " << v;
          standing[v] = std::move(witness);
          continue;
        } catch (const VertexRemovalError&) {
          continue;
        }
        ++deleted;
        std::erase_if(standing, [&](const auto& entry) { return std::find(entry.second.begin(), entry.second.end(), v) != entry.second.end(); });
        for (const auto& entry : standing) {
          const uint32_t u = entry.first;
          ++retried;
          try {
            mesh.remove_vertex(u);
            ADD_FAILURE() << "vertex " << u << " deleted after " << v << " went, its early refusal's witness intact";
          } catch (const NoCdtError& e) {
            EXPECT_TRUE(early(e)) << "vertex " << u << ": " << e.what();
          } catch (const VertexRemovalError& e) {  // its pieces bent since: the same test, a guess now
            EXPECT_TRUE(guessed(e)) << "vertex " << u << ": " << e.what();
          }
        }
      }
    std::cout << "[ fins ] " << (noise ? "noisy" : "exact") << ": " << deleted << " deleted, " << refusals << " refused early, "
              << retried << " of those tried again while their witness stayed\n";
    EXPECT_GT(refusals, 10);
    EXPECT_GT(retried, 100);
  }
}

// guess_blocked_refusals(): a Steiner point rounded off its segment (CAD noise: double coordinates)
// whose merged segment is not Delaunay among its star's vertices is refused before its cavity is
// built, where that test proves nothing: only when asked, and then nearly always as the star CDT
// decides. Each guessed refusal is tried again exactly (the guess off): a deletion the star CDT
// accepts is a wrong guess, and is made, so the pass goes on as the exact one would.
TEST(EditableCdt, GuessedRefusalsOnlyWhenAskedAndMostlyAsTheStarCdtDecides) {
  const Plc<3> fins = sweepcdt::testing::noisy_fins(2);
  Options options = mesh_defaults();
  options.remove_steiner_points = false;
  options.algorithm = Algorithm::SweepPlane;  // every segment refined
  Plc<3> refined;
  const Triangulation<3> tri = cdt(fins, options, &refined);
  ASSERT_GT(tri.steiner_on.size(), 20u);
  EditableCdt<3> mesh(refined, tri);
  mesh.unbend_facets_at_steiner_points(1000);
  const auto guessed = [](const std::exception& e) { return std::string(e.what()).find("lies off that segment or its facets are bent") != std::string::npos; };
  int guesses = 0, right = 0, wrong = 0, deleted = 0, exact_guesses = 0;
  for (int pass = 0; pass < 2; ++pass)
    for (uint32_t v = tri.num_input_points; v < tri.num_points(); ++v) {
      if (!mesh.has_vertex(v)) continue;
      const bool asked = pass == 0 || v % 2 == 0;  // the second pass asks for every other point only
      mesh.guess_blocked_refusals(asked);
      try {
        mesh.remove_vertex(v);
        ++deleted;
        continue;
      } catch (const VertexRemovalError& e) {
        if (!guessed(e)) continue;
        exact_guesses += !asked;
      } catch (const NoCdtError&) {
        continue;
      }
      ++guesses;
      mesh.guess_blocked_refusals(false);
      try {
        mesh.remove_vertex(v);
        ++wrong, ++deleted;
      } catch (const NoCdtError&) {
        ++right;
      } catch (const VertexRemovalError& e) {
        ++right;
        EXPECT_FALSE(guessed(e)) << "vertex " << v << ": guessed with the guess off";
      }
    }
  std::cout << "[ fins ] noisy: " << tri.steiner_on.size() << " Steiner points, " << deleted << " deleted, " << guesses
            << " refusals guessed: " << right << " as the star CDT decides, " << wrong << " not\n";
  EXPECT_EQ(exact_guesses, 0) << "refusals guessed with the guess off";
  EXPECT_GT(guesses, 10);
  EXPECT_LE(10 * wrong, guesses);
  EXPECT_GT(deleted, 10);
}

// release() hands the mesh's own arrays over, compacted in place (no second copy at the end of the
// deletion pass); it must give exactly what snapshot() gives: after deletions (dead slots and
// constraints between live ones), with regions and tags, and with a
// perturbation rank (the identity here, which the snapshot must renumber for the vertices left).
TEST(EditableCdt, ReleaseGivesWhatSnapshotGives) {
  const Plc<3> fins = sweepcdt::testing::noisy_fins(2);
  Options options = mesh_defaults();
  options.remove_steiner_points = false;
  options.algorithm = Algorithm::SweepPlane;
  Plc<3> refined;
  Triangulation<3> tri = cdt(fins, options, &refined);
  ASSERT_GT(tri.steiner_on.size(), 20u);
  ASSERT_FALSE(tri.regions.empty());
  for (const bool ranked : {false, true}) {
    Triangulation<3> start = tri;
    if (ranked) {
      start.perturbation_rank.resize(start.num_points());
      std::iota(start.perturbation_rank.begin(), start.perturbation_rank.end(), 0u);
    }
    EditableCdt<3> mesh(refined, start);
    mesh.unbend_facets_at_steiner_points(1000);
    int deleted = 0;
    for (uint32_t v = tri.num_input_points; v < tri.num_points(); v += 2) {
      try {
        mesh.remove_vertex(v);
        ++deleted;
      } catch (const NoCdtError&) {
      } catch (const VertexRemovalError&) {
      }
    }
    ASSERT_GT(deleted, 10);
    const EditableCdt<3>::Snapshot copy = mesh.snapshot();
    const EditableCdt<3>::Snapshot own = std::move(mesh).release();
    EXPECT_EQ(own.old_ids, copy.old_ids);
    EXPECT_EQ(own.triangulation.points, copy.triangulation.points);
    EXPECT_EQ(own.triangulation.num_input_points, copy.triangulation.num_input_points);
    EXPECT_EQ(own.triangulation.steiner_on, copy.triangulation.steiner_on);
    EXPECT_EQ(own.triangulation.perturbation_rank, copy.triangulation.perturbation_rank);
    EXPECT_EQ(own.triangulation.perturbation_rank.empty(), !ranked);
    EXPECT_EQ(own.triangulation.simplices, copy.triangulation.simplices);
    EXPECT_EQ(own.triangulation.neighbors, copy.triangulation.neighbors);
    EXPECT_EQ(own.triangulation.regions, copy.triangulation.regions);
    EXPECT_EQ(own.plc.points, copy.plc.points);
    EXPECT_EQ(own.plc.simplices, copy.plc.simplices);
    EXPECT_EQ(own.plc.exterior, copy.plc.exterior);
    EXPECT_EQ(own.plc.tags, copy.plc.tags);
    EXPECT_EQ(own.plc.region_seeds.size(), copy.plc.region_seeds.size());
    // Checked apart from the shared assembly: each vertex left is the point it was, numbered in
    // the same order, and the snapshot is a valid CDT of its PLC, the one cdt() computes from scratch.
    ASSERT_EQ(own.triangulation.num_points(), own.old_ids.size());
    for (std::size_t i = 0; i < own.old_ids.size(); ++i) {
      if (i > 0) EXPECT_LT(own.old_ids[i - 1], own.old_ids[i]);
      EXPECT_TRUE(std::equal(refined.point(own.old_ids[i]), refined.point(own.old_ids[i]) + 3, own.triangulation.points.data() + 3 * i)) << i;
    }
    Triangulation<3> whole = own.triangulation;
    whole.num_input_points = static_cast<uint32_t>(own.plc.num_points());
    whole.steiner_on.clear();
    EXPECT_TRUE(validate(whole, own.plc).ok());
    EXPECT_EQ(fixtures::simplex_set(own.triangulation), fixtures::simplex_set(cdt(own.plc)));
  }
}

TEST(EditableCdt, RefusesCornersAndUnknownVertices) {
  const Plc<3> cube = fixtures::unit_cube_surface();
  EditableCdt<3> mesh(cube, cdt(cube));
  EXPECT_THROW(mesh.remove_vertex(0), VertexRemovalError);   // a corner
  EXPECT_THROW(mesh.remove_vertex(99), VertexRemovalError);  // no such vertex
  EXPECT_EQ(mesh.num_vertices(), 8u);
}

// remove_vertex() in two steps (plan_removal, commit_removal): every Steiner point of a refined
// PLC is planned at once on the first state, on two threads, then the plans are committed in some
// order. Each commit must do what remove_vertex() does in that order on a second copy — the same
// vertices deleted or refused, with the same neighbours, and the same CDT in the end — although
// most plans were made before earlier commits changed their stars or the simplices next to them
// (those are worked out again; the others are used as made).
TEST(EditableCdt, PlansCommittedInOrderAgreeWithRemoveVertex) {
  std::vector<double> xs{0, 1}, tops{0.2};
  for (int fin = 0; fin < 5; ++fin) {
    xs.push_back(xs.back() + 0.02);  // thin fins: many Steiner points, many of them deletable
    tops.push_back(1.0);
    xs.push_back(xs.back() + 0.2);
    tops.push_back(0.2);
  }
  const Plc<3> comb = fixtures::extruded_columns(xs, tops, 1.0);
  Options options;
  options.steiner = SteinerMode::Auto;
  options.remove_steiner_points = false;
  Plc<3> refined;
  const Triangulation<3> tri = cdt(comb, options, &refined);
  const uint32_t first = tri.num_input_points, end = static_cast<uint32_t>(tri.num_points());
  ASSERT_GT(end - first, 50u);

  std::vector<uint32_t> order;
  for (uint32_t v = end; v-- > first;) order.push_back(v);  // last added first
  for (const std::string how : {"last first", "first first", "shuffled"}) {
    if (how == "first first") std::reverse(order.begin(), order.end());
    if (how == "shuffled") std::shuffle(order.begin(), order.end(), std::mt19937_64(5));
    EditableCdt<3> planned(refined, tri), stepped(refined, tri);
    std::vector<EditableCdt<3>::Removal> plans(end - first);
    std::thread helper([&] {
      for (uint32_t v = first + 1; v < end; v += 2) plans[v - first] = planned.plan_removal(v);
    });
    for (uint32_t v = first; v < end; v += 2) plans[v - first] = planned.plan_removal(v);
    helper.join();

    int deleted = 0;
    for (uint32_t v : order) {
      std::string outcome_planned = "deleted", outcome_stepped = "deleted";
      std::vector<uint32_t> neighbours_planned, neighbours_stepped;
      try {
        neighbours_planned = planned.commit_removal(std::move(plans[v - first]));
      } catch (const Error& e) {
        outcome_planned = e.what();
      }
      try {
        neighbours_stepped = stepped.remove_vertex(v);
        ++deleted;
      } catch (const Error& e) {
        outcome_stepped = e.what();
      }
      ASSERT_EQ(outcome_planned, outcome_stepped) << how << ", vertex " << v;
      ASSERT_EQ(neighbours_planned, neighbours_stepped) << how << ", vertex " << v;
      const auto a = planned.snapshot(), b = stepped.snapshot();  // the neighbour links too, after every step
      ASSERT_EQ(a.triangulation.neighbors, b.triangulation.neighbors) << how << ", vertex " << v;
    }
    const auto a = planned.snapshot(), b = stepped.snapshot();
    EXPECT_EQ(a.triangulation.simplices, b.triangulation.simplices) << how;
    EXPECT_EQ(a.triangulation.neighbors, b.triangulation.neighbors) << how;
    EXPECT_EQ(a.plc.simplices, b.plc.simplices) << how;
    const auto report = validate_triangulated(a.triangulation, a.plc);
    EXPECT_TRUE(report.ok()) << how << "\n" << report.summary();
    std::cout << "[ plans ] " << how << ": " << end - first << " Steiner points, " << deleted << " deleted, "
              << planned.plans_redone() << " plans worked out again\n";
    EXPECT_GT(deleted, 10) << how;
    EXPECT_GT(planned.plans_redone(), 0u) << how << ": no stale plan, working a plan out again is not exercised";
    EXPECT_LT(planned.plans_redone(), static_cast<uint64_t>(end - first)) << how << ": every plan stale, using one as made is not exercised";
    EXPECT_THROW(planned.commit_removal(std::move(plans[0])), std::invalid_argument) << how;  // committed already
  }
}
