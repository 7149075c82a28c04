// validate(): exact check that a triangulation is the CDT of a PLC. What is checked and why it
// suffices is documented in validate.h.
#include "ids_text.h"
#include "sweepcdt/validate.h"

#include <algorithm>
#include <map>
#include <string>

#include "box_tree.h"
#include "parallel.h"
#include "facets.h"
#include "simplex_intersection.h"
#include "sweepcdt/predicates/exact_sum.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"

namespace sweepcdt {
namespace {

using predicates::Sign;
using detail::ids_text;
constexpr std::size_t kReportedPerCheck = 10;

std::string n(uint64_t i) { return std::to_string(i); }

template <int D>
class Validator {
 public:
  Validator(const Triangulation<D>& tri, const Plc<D>& plc, unsigned threads) : tri_(tri), plc_(plc), threads_(threads) {}

  ValidationReport run(ValidationLevel level) {
    if (!shapes() || !simplex_ids()) return std::move(report_);
    orientation();
    facets_ = detail::sorted_facets(tri_, threads_);
    group_facets();
    neighbors();
    interior_facet_sides();
    steiner_points();
    constraints();
    domain();
    volume();
    regions();
    if (level == ValidationLevel::Full) locally_delaunay();
    return std::move(report_);
  }

 private:
  // One group of equal facets: entries [begin, end) of facets_.
  struct Group {
    uint32_t begin, end;          // 32 bits: 4 G facet entries are far beyond any triangulation here
    uint32_t constraint = kNone;  // the constraining simplex this facet lies in
  };

  void fail(const std::string& check, const std::string& detail) { fail_in(report_, check, detail); }
  static void fail_in(ValidationReport& report, const std::string& check, const std::string& detail) {
    if (report.counts[check]++ < kReportedPerCheck) report.failures.push_back({check, detail});
  }

  // test(i, fail) for every i in [0, n), in parts on threads_ (parallel.h); the failures are reported
  // as one pass in order would report them.
  template <class Test>
  void in_parts(std::size_t n, Test&& test) {
    std::vector<ValidationReport> parts(detail::parts_for(n, threads_));
    detail::for_each_part(n, threads_, [&](std::size_t part, std::size_t begin, std::size_t end) {
      const auto fail_here = [&](const std::string& check, const std::string& what) { fail_in(parts[part], check, what); };
      for (std::size_t i = begin; i < end; ++i) test(i, fail_here);
    });
    for (ValidationReport& part : parts)
      detail::append_part(report_.failures, report_.counts, std::move(part.failures), part.counts, kReportedPerCheck,
                          [](const ValidationReport::Failure& f) { return f.check; });
  }

  predicates::Coords<D + 1> coords(uint32_t t) const {
    predicates::Coords<D + 1> c;
    for (int i = 0; i <= D; ++i) c[i] = tri_.point(tri_.simplex(t)[i]);
    return c;
  }
  // The simplex t with its vertex `local` replaced by point p.
  Sign orient_replaced(uint32_t t, uint32_t local, const double* p) const {
    auto c = coords(t);
    c[local] = p;
    return predicates::orient<D>(c);
  }
  std::array<const double*, D> constraint_coords(std::size_t j) const {
    std::array<const double*, D> c;
    for (int i = 0; i < D; ++i) c[i] = tri_.point(plc_.simplex(j)[i]);
    return c;
  }
  std::string simplex_text(uint32_t t) const { return "simplex " + n(t) + " " + ids_text(tri_.simplex(t), D + 1); }
  std::string facet_text(const Group& g) const { return "facet " + ids_text(facets_[g.begin].key.data(), D); }
  uint32_t apex(const detail::FacetEntry<D>& e) const { return tri_.simplex(e.simplex)[e.local]; }

  bool shapes() {
    bool ok = true;
    auto require = [&](bool condition, const std::string& what) {
      if (!condition) fail("shape", what), ok = false;
    };
    require(tri_.points.size() % D == 0, "points: size is not a multiple of D");
    require(tri_.simplices.size() % (D + 1) == 0, "simplices: size is not a multiple of D+1");
    require(tri_.simplices.size() < (uint64_t{1} << 32), "simplices: 2^32 vertex entries or more (facets are numbered in 32 bits)");
    require(tri_.neighbors.empty() || tri_.neighbors.size() == tri_.simplices.size(), "neighbors: size differs from simplices");
    require(tri_.regions.empty() || tri_.regions.size() == tri_.num_simplices(), "regions: one per simplex expected");
    require(tri_.num_input_points == plc_.num_points(), "num_input_points differs from the PLC's point count");
    require(tri_.num_points() >= tri_.num_input_points &&
                tri_.steiner_on.size() == tri_.num_points() - tri_.num_input_points,
            "steiner_on: one entry per Steiner point expected");
    const auto& rank = tri_.perturbation_rank;
    require(rank.empty() || rank.size() == tri_.num_points(), "perturbation_rank: one entry per point expected");
    if (!ok) return false;
    std::vector<char> ranked(rank.size(), 0);
    for (const uint32_t r : rank)
      if (r >= rank.size() || ranked[r]++) {
        fail("shape", "perturbation_rank is not a permutation of the point ids");
        return false;
      }
    if (!std::equal(plc_.points.begin(), plc_.points.end(), tri_.points.begin()))
      fail("points", "the input points are not preserved exactly as the first num_input_points points");
    return true;
  }

  bool simplex_ids() {
    bool ok = true;
    for (uint32_t t = 0; t < tri_.num_simplices(); ++t) {
      std::array<uint32_t, D + 1> ids;
      std::copy_n(tri_.simplex(t), D + 1, ids.begin());
      if (std::any_of(ids.begin(), ids.end(), [&](uint32_t i) { return i >= tri_.num_points(); })) {
        fail("simplex-ids", simplex_text(t) + " names a point that does not exist");
        ok = false;
        continue;
      }
      std::sort(ids.begin(), ids.end());
      if (std::adjacent_find(ids.begin(), ids.end()) != ids.end()) fail("simplex-ids", simplex_text(t) + " repeats a vertex"), ok = false;
    }
    return ok;
  }

  void orientation() {
    positive_.assign(tri_.num_simplices(), 0);
    in_parts(tri_.num_simplices(), [&](std::size_t i, const auto& fail_here) {
      const uint32_t t = static_cast<uint32_t>(i);
      if (predicates::orient<D>(coords(t)) == Sign::Positive) positive_[t] = 1;
      else fail_here("orientation", simplex_text(t) + " is not positively oriented (inverted or flat)");
    });
  }

  // Counted first, so that the list is allocated once (3.8M groups at 1.3M triangles: growing it
  // by doubling cost 0.6 s, copies and fresh pages).
  void group_facets() {
    std::size_t count = 0;
    detail::for_each_facet_group<D>(facets_, [&](std::size_t, std::size_t) { ++count; });
    groups_.reserve(count);
    detail::for_each_facet_group<D>(facets_, [&](std::size_t begin, std::size_t end) {
      groups_.push_back({static_cast<uint32_t>(begin), static_cast<uint32_t>(end)});
      if (end - begin > 2) fail("facet-multiplicity", facet_text(groups_.back()) + " is shared by " + n(end - begin) + " simplices");
    });
  }

  void neighbors() {
    if (tri_.neighbors.empty()) return;
    std::vector<uint32_t> expected(tri_.simplices.size(), kNone);
    for (const Group& g : groups_) {
      if (g.end - g.begin != 2) continue;
      const auto& a = facets_[g.begin];
      const auto& b = facets_[g.begin + 1];
      expected[(D + 1) * a.simplex + a.local] = (D + 1) * b.simplex + b.local;
      expected[(D + 1) * b.simplex + b.local] = (D + 1) * a.simplex + a.local;
    }
    for (std::size_t k = 0; k < expected.size(); ++k)
      if (expected[k] != tri_.neighbors[k])
        fail("neighbors", "neighbour " + n(k % (D + 1)) + " of " + simplex_text(static_cast<uint32_t>(k / (D + 1))) +
                              " is " + n(tri_.neighbors[k]) + ", expected " + n(expected[k]));
  }

  // Whether simplex a with its vertex a.local replaced by b's apex is negatively oriented: b lies on
  // the other side of their common facet. Both are the same vertex set, so when orientation() found
  // b positive, that orientation is b's times the parity of the permutation between the two vertex
  // orders: no predicate needed (a third of the orientations of a D = 4 validation).
  Sign side_of_apex(const detail::FacetEntry<D>& a, const detail::FacetEntry<D>& b) const {
    if (!positive_[b.simplex]) return orient_replaced(a.simplex, a.local, tri_.point(apex(b)));
    std::array<uint32_t, D + 1> replaced, other;
    std::copy_n(tri_.simplex(a.simplex), D + 1, replaced.begin());
    replaced[a.local] = apex(b);
    std::copy_n(tri_.simplex(b.simplex), D + 1, other.begin());
    return detail::odd_permutation(replaced) == detail::odd_permutation(other) ? Sign::Positive : Sign::Negative;
  }

  void interior_facet_sides() {
    in_parts(groups_.size(), [&](std::size_t i, const auto& fail_here) {
      const Group& g = groups_[i];
      if (g.end - g.begin != 2) return;
      const auto& a = facets_[g.begin];
      const auto& b = facets_[g.begin + 1];
      if (side_of_apex(a, b) != Sign::Negative)
        fail_here("interior-facet-sides", facet_text(g) + ": simplices " + n(a.simplex) + " and " + n(b.simplex) + " are not on opposite sides");
    });
  }

  // Steiner points must lie on the constraining simplex recorded for them.
  void steiner_points() {
    for (std::size_t k = 0; k < tri_.steiner_on.size(); ++k) {
      const uint32_t c = tri_.steiner_on[k];
      if (c == kNone) continue;
      const double* p = tri_.point(static_cast<uint32_t>(tri_.num_input_points + k));
      if (c >= plc_.num_simplices() || !detail::point_in_simplex<D>(p, constraint_coords(c)))
        fail("steiner-points", "Steiner point " + n(tri_.num_input_points + k) + " is not on constraining simplex " + n(c));
    }
  }

  const Group* find_group(const detail::FacetKey<D>& key) const {
    const auto it = std::lower_bound(facets_.begin(), facets_.end(), key,
                                     [](const detail::FacetEntry<D>& e, const detail::FacetKey<D>& k) { return e.key < k; });
    if (it == facets_.end() || it->key != key) return nullptr;
    const std::size_t index = static_cast<std::size_t>(it - facets_.begin());
    const auto g = std::lower_bound(groups_.begin(), groups_.end(), index, [](const Group& gr, std::size_t i) { return gr.end <= i; });
    return &*g;
  }

  void constraints() {
    std::vector<std::vector<uint32_t>> steiner_on_constraint = steiner_points_by_constraint();
    // Each constraint's facet group looked up in parts (two binary searches each), then marked in order.
    std::vector<uint32_t> group_of(plc_.num_simplices(), kNone);
    detail::for_each_part(plc_.num_simplices(), threads_, [&](std::size_t, std::size_t begin, std::size_t end) {
      for (std::size_t j = begin; j < end; ++j) {
        detail::FacetKey<D> key;
        std::copy_n(plc_.simplex(j), D, key.begin());
        std::sort(key.begin(), key.end());
        if (const Group* g = find_group(key)) group_of[j] = static_cast<uint32_t>(g - groups_.data());
      }
    });
    for (std::size_t j = 0; j < plc_.num_simplices(); ++j) {
      if (group_of[j] != kNone) {
        groups_[group_of[j]].constraint = static_cast<uint32_t>(j);
        continue;
      }
      if (steiner_on_constraint[j].empty() || !covered_by_facets(j, steiner_on_constraint[j]))
        fail("constraints", "constraining simplex " + n(j) + " " + ids_text(plc_.simplex(j), D) + " is not a union of facets");
    }
  }

  // For each constraining simplex, the Steiner points lying on it (found geometrically, not trusted
  // from steiner_on: a point on a shared edge lies on several constraints).
  std::vector<std::vector<uint32_t>> steiner_points_by_constraint() const {
    std::vector<std::vector<uint32_t>> on(plc_.num_simplices());
    if (tri_.num_points() == tri_.num_input_points || plc_.num_simplices() == 0) return on;
    std::vector<detail::Box<D>> boxes(plc_.num_simplices());
    for (std::size_t j = 0; j < boxes.size(); ++j) boxes[j] = detail::Box<D>::of_points(constraint_coords(j).data(), D);
    const detail::BoxTree<D> tree(std::move(boxes));
    for (uint32_t v = tri_.num_input_points; v < tri_.num_points(); ++v) {
      const double* p = tri_.point(v);
      tree.for_each_overlap(detail::Box<D>::of_points(&p, 1), [&](uint32_t j) {
        if (detail::point_in_simplex<D>(p, constraint_coords(j))) on[j].push_back(v);
      });
    }
    return on;
  }

  // Facets whose vertices all lie on constraint j tile it iff their projected measures add up to its
  // own (they cannot overlap once the other checks pass). Marks them as lying in j.
  bool covered_by_facets(std::size_t j, const std::vector<uint32_t>& steiner) {
    std::vector<uint32_t> on(plc_.simplex(j), plc_.simplex(j) + D);
    on.insert(on.end(), steiner.begin(), steiner.end());
    std::sort(on.begin(), on.end());
    auto is_on = [&](uint32_t v) { return std::binary_search(on.begin(), on.end(), v); };
    const auto c = constraint_coords(j);
    int drop = 0;
    while (drop < D && predicates::orient_projected<D>(c, drop) == Sign::Zero) ++drop;
    predicates::ExactMeasureSum whole, parts;
    whole.add_projected_measure<D>(c, drop);
    for (Group& g : groups_) {
      const auto& key = facets_[g.begin].key;
      if (!std::all_of(key.begin(), key.end(), is_on)) continue;
      std::array<const double*, D> f;
      for (int i = 0; i < D; ++i) f[i] = tri_.point(key[i]);
      parts.add_projected_measure<D>(f, drop);
      g.constraint = static_cast<uint32_t>(j);
    }
    return whole.compare(parts) == Sign::Zero;
  }

  // Which side of constraint j the simplex of facet entry e is on: the sign of orient(constraint, apex).
  Sign side_of_constraint(std::size_t j, const detail::FacetEntry<D>& e) const {
    predicates::Coords<D + 1> c;
    const auto f = constraint_coords(j);
    std::copy(f.begin(), f.end(), c.begin());
    c[D] = tri_.point(apex(e));
    return predicates::orient<D>(c);
  }

  Sign exterior_sign(uint32_t j) const { return plc_.exterior_of(j) == ExteriorSide::Positive ? Sign::Positive : Sign::Negative; }

  // The group's facet has exactly the vertices of its constraint (no Steiner point subdivides it).
  bool is_the_constraint(const Group& g) const {
    detail::FacetKey<D> key;
    std::copy_n(plc_.simplex(g.constraint), D, key.begin());
    std::sort(key.begin(), key.end());
    return key == facets_[g.begin].key;
  }

  void domain() {
    if (plc_.facet_bounded()) facet_bounded_domain();
    else convex_hull_domain();
  }

  void facet_bounded_domain() {
    for (const Group& g : groups_) {
      const std::size_t count = g.end - g.begin;
      const ExteriorSide ext = g.constraint == kNone ? ExteriorSide::None : plc_.exterior_of(g.constraint);
      if (ext == ExteriorSide::None) {
        if (count == 1)
          fail("domain-boundary", facet_text(g) + " bounds the triangulation but is not an exterior-notated constraining simplex");
        continue;
      }
      bool domain_side = false;
      for (std::size_t k = g.begin; k < g.end; ++k) {
        if (side_of_constraint(g.constraint, facets_[k]) == exterior_sign(g.constraint))
          fail("domain-boundary", simplex_text(facets_[k].simplex) + " lies on the exterior side of constraining simplex " + n(g.constraint));
        else
          domain_side = true;
      }
      if (!domain_side) fail("domain-boundary", facet_text(g) + " of constraining simplex " + n(g.constraint) + " has no simplex on its domain side");
    }
    unused_points_outside();
  }

  // An input point that is no vertex must lie outside every simplex (closed).
  void unused_points_outside() {
    std::vector<char> used(tri_.num_points(), 0);
    for (uint32_t v : tri_.simplices) used[v] = 1;
    if (std::all_of(used.begin(), used.begin() + tri_.num_input_points, [](char u) { return u; })) return;
    std::vector<detail::Box<D>> boxes(tri_.num_simplices());
    for (uint32_t t = 0; t < boxes.size(); ++t) boxes[t] = detail::Box<D>::of_points(coords(t).data(), D + 1);
    const detail::BoxTree<D> tree(std::move(boxes));
    for (uint32_t v = 0; v < tri_.num_input_points; ++v) {
      if (used[v]) continue;
      const double* p = tri_.point(v);
      bool inside = false;
      tree.for_each_overlap(detail::Box<D>::of_points(&p, 1), [&](uint32_t t) {
        bool in = true;
        for (uint32_t i = 0; i <= D && in; ++i) in = orient_replaced(t, i, p) != Sign::Negative;
        inside |= in;
      });
      if (inside) fail("unused-vertex", "input point " + n(v) + " lies in the triangulated domain but is not a vertex");
    }
  }

  void convex_hull_domain() {
    std::vector<char> used(tri_.num_points(), 0);
    for (uint32_t v : tri_.simplices) used[v] = 1;
    for (uint32_t v = 0; v < tri_.num_input_points; ++v)
      if (!used[v]) fail("unused-vertex", "input point " + n(v) + " is not a vertex of the triangulation of its convex hull");

    // The boundary must be a closed pseudo-manifold (two boundary facets per boundary ridge) that is
    // locally convex at every ridge; with every input point a vertex, that makes it the hull boundary.
    std::vector<const detail::FacetEntry<D>*> boundary;
    for (const Group& g : groups_)
      if (g.end - g.begin == 1) boundary.push_back(&facets_[g.begin]);
    std::map<std::array<uint32_t, D - 1>, std::vector<std::size_t>> ridges;
    for (std::size_t b = 0; b < boundary.size(); ++b)
      for (int drop = 0; drop < D; ++drop) {
        std::array<uint32_t, D - 1> r;
        for (int i = 0, k = 0; i < D; ++i)
          if (i != drop) r[k++] = boundary[b]->key[i];
        ridges[r].push_back(b);
      }
    for (const auto& [ridge, faces] : ridges) {
      if (faces.size() != 2) {
        fail("domain-boundary", "a boundary ridge " + ids_text(ridge.data(), D - 1) + " has " + n(faces.size()) + " boundary facets, not 2");
        continue;
      }
      for (int k = 0; k < 2; ++k) {
        const auto* f = boundary[faces[k]];
        const auto* other = boundary[faces[1 - k]];
        for (uint32_t v : other->key)
          if (!std::binary_search(f->key.begin(), f->key.end(), v) &&
              orient_replaced(f->simplex, f->local, tri_.point(v)) == Sign::Negative)
            fail("domain-boundary", "the boundary is not convex at ridge " + ids_text(ridge.data(), D - 1));
      }
    }
    // Then every point against every boundary facet directly (up to 20M tests), which rules out a
    // boundary of several convex pieces. Only the boundary's vertices need it: the domain is compact,
    // so it lies in the convex hull of its boundary, hence of those vertices, and each input point is
    // a vertex (above), so it lies in the domain; all inside every facet's half-space then means all
    // are. (Random points in a 4-cube: a tenth of the points are on the hull, and this test was 40%
    // of the run when it took every point.)
    std::vector<uint32_t> on_boundary;
    for (const auto* f : boundary) on_boundary.insert(on_boundary.end(), f->key.begin(), f->key.end());
    std::sort(on_boundary.begin(), on_boundary.end());
    on_boundary.erase(std::unique(on_boundary.begin(), on_boundary.end()), on_boundary.end());
    if (boundary.size() * on_boundary.size() <= 20'000'000)
      for (const auto* f : boundary)
        for (const uint32_t v : on_boundary)
          if (orient_replaced(f->simplex, f->local, tri_.point(v)) == Sign::Negative) {
            fail("domain-boundary", "point " + n(v) + " lies outside boundary " + simplex_text(f->simplex));
            break;
          }
  }

  // Sum of simplex volumes = volume of the domain, computed from its notated boundary as a sum of
  // cones from point 0 (divergence theorem): each boundary piece oriented with the domain on its
  // positive side. Both sides are exact sums, and two exact identities keep them short:
  //  - a simplex's volume is the sum of the cones from point 0 over its facets (multilinearity), and
  //    at an interior facet whose two simplices lie on opposite sides the two cones cancel; so where
  //    the facets pair up like that (interior_facet_sides() and group_facets() report every facet
  //    that does not), the simplices' volume is the sum of the cones over the boundary facets;
  //  - a boundary facet that is a notated constraint itself, its simplex on the domain side, has
  //    exactly that constraint's cone, and the two terms cancel.
  // What is left to add up is the boundary that Steiner points subdivide (and whatever other checks
  // found wrong). A convex hull domain's boundary is the boundary facets themselves, so the identity
  // alone makes its two sums equal: nothing to compare.
  void volume() {
    if (tri_.num_points() == 0 || !plc_.facet_bounded()) return;
    predicates::ExactMeasureSum simplices, domain;
    const double* origin = tri_.point(0);
    std::vector<char> cancelled(plc_.num_simplices(), 0);
    for (const Group& g : groups_) {
      if (g.end - g.begin != 1) continue;
      const auto& e = facets_[g.begin];
      if (g.constraint != kNone && is_the_constraint(g) && plc_.exterior_of(g.constraint) != ExteriorSide::None &&
          side_of_constraint(g.constraint, e) != exterior_sign(g.constraint)) {
        cancelled[g.constraint] = 1;
        continue;
      }
      auto cone = coords(e.simplex);
      cone[e.local] = origin;
      simplices.add_volume<D>(cone);
    }
    for (std::size_t j = 0; j < plc_.num_simplices(); ++j) {
      const ExteriorSide ext = plc_.exterior_of(j);
      if (ext == ExteriorSide::None || cancelled[j]) continue;
      predicates::Coords<D + 1> cone;
      const auto c = constraint_coords(j);
      std::copy(c.begin(), c.end(), cone.begin());
      cone[D] = origin;
      domain.add_volume<D>(cone, ext == ExteriorSide::Positive);
    }
    if (simplices.compare(domain) != Sign::Zero)
      fail("domain-volume", "the simplices' volume " + std::to_string(simplices.to_double()) +
                                " differs from the domain's " + std::to_string(domain.to_double()) + " (times D!)");
  }

  void regions() {
    if (tri_.regions.empty()) return;
    for (const Group& g : groups_) {
      if (g.end - g.begin != 2 || g.constraint != kNone) continue;
      const uint32_t a = facets_[g.begin].simplex, b = facets_[g.begin + 1].simplex;
      if (tri_.regions[a] != tri_.regions[b])
        fail("regions", "simplices " + n(a) + " and " + n(b) + " share an unconstrained facet but have regions " +
                            std::to_string(tri_.regions[a]) + " and " + std::to_string(tri_.regions[b]));
    }
  }

  // Point v as the perturbation sees it: ordered by tri.perturbation_rank when cdt() had to try
  // another order (paper §6, sweepcdt/perturbation_order.h), else by id.
  predicates::Vertex perturbed(uint32_t v) const {
    return {tri_.point(v), tri_.perturbation_rank.empty() ? v : tri_.perturbation_rank[v]};
  }

  // Paper §1/§6: with the constraints present, a triangulation whose unconstrained interior facets
  // are all locally Delaunay (perturbed) is the CDT.
  void locally_delaunay() {
    in_parts(groups_.size(), [&](std::size_t i, const auto& fail_here) {
      const Group& g = groups_[i];
      if (g.end - g.begin != 2 || g.constraint != kNone) return;
      const auto& a = facets_[g.begin];
      const auto& b = facets_[g.begin + 1];
      predicates::Vertices<D + 1> s;
      for (int k = 0; k <= D; ++k) s[k] = perturbed(tri_.simplex(a.simplex)[k]);
      const uint32_t q = apex(b);
      if (predicates::inside_circumsphere<D>(s, perturbed(q)))
        fail_here("locally-delaunay", facet_text(g) + " is not locally Delaunay: point " + n(q) + " is inside the circumsphere of " +
                                          simplex_text(a.simplex));
    });
  }

  const Triangulation<D>& tri_;
  const Plc<D>& plc_;
  ValidationReport report_;
  detail::FacetList<D> facets_;
  std::vector<Group> groups_;
  std::vector<uint8_t> positive_;  // per simplex: orientation() found it positively oriented
  unsigned threads_;
};

}  // namespace

std::string ValidationReport::summary() const {
  if (ok()) return "valid";
  std::string s;
  for (const auto& f : failures) s += f.check + ": " + f.detail + "\n";
  for (const auto& [check, count] : counts) s += check + ": " + std::to_string(count) + " failure" + (count == 1 ? "" : "s") + "\n";
  return s;
}

template <int D>
ValidationReport validate(const Triangulation<D>& tri, const Plc<D>& plc, ValidationLevel level, unsigned threads) {
  return Validator<D>(tri, plc, threads).run(level);
}

template ValidationReport validate<2>(const Triangulation<2>&, const Plc<2>&, ValidationLevel, unsigned);
template ValidationReport validate<3>(const Triangulation<3>&, const Plc<3>&, ValidationLevel, unsigned);
template ValidationReport validate<4>(const Triangulation<4>&, const Plc<4>&, ValidationLevel, unsigned);
template ValidationReport validate<5>(const Triangulation<5>&, const Plc<5>&, ValidationLevel, unsigned);

}  // namespace sweepcdt
