// Sheets through a deleted vertex and their new triangulations (sheets.h).
#include "sheets.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>

#include "../ids_text.h"
#include "../segment_interior.h"
#include "../triangle_normal.h"
#include "../steiner/facet_groups.h"  // edge_key
#include "sweepcdt/editable_cdt.h"
#include "sweepcdt/predicates/orientation.h"
#include "sweepcdt/predicates/perturbation.h"
#include "../sweep/sweep_cdt.h"
#include "sweepcdt/validate.h"

namespace sweepcdt::detail {
namespace {

using predicates::Sign;

struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) { return parent[x] == x ? x : parent[x] = find(parent[x]); }
  void unite(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

template <int D>
class SheetBuilder {
 public:
  SheetBuilder(uint32_t v, const std::vector<std::array<uint32_t, D>>& through_v, const std::function<const double*(uint32_t)>& point,
               const std::function<uint32_t(uint32_t)>& order, const std::function<bool(uint32_t, uint32_t)>& same_facet, const Unbend* unbend)
      : v_(v), through_v_(through_v), point_(point), order_(order), same_facet_(same_facet), unbend_(unbend) {}

  // The sheets, or none with the reason in `refusal_` (v cannot be deleted).
  std::vector<Sheet<D>> run() {
    // Ridges through v (a constraint without one of its other vertices), each with a constraint on
    // it, sorted: the constraints on one ridge are neighbours.
    for (uint32_t c = 0; c < through_v_.size(); ++c)
      for (int i = 0; i < D; ++i)
        if (through_v_[c][i] != v_) ridges_.push_back({ridge(c, i), c});
    std::sort(ridges_.begin(), ridges_.end());
    UnionFind sheets(through_v_.size());
    for (std::size_t k = 0; k < ridges_.size();) {
      const std::size_t on = constraints_on(ridges_[k].first);
      if (on == 2) {
        const uint32_t a = ridges_[k].second, b = ridges_[k + 1].second;
        if (same_facet_(a, b) && (unbend_ || coplanar(a, b)) && opposite(a, b, ridges_[k].first)) sheets.unite(a, b);
      }
      k += on;
    }
    // One sheet per root, in the order of the roots.
    std::vector<char> is_root(through_v_.size(), 0);
    for (uint32_t c = 0; c < through_v_.size(); ++c) is_root[sheets.find(c)] = 1;
    std::vector<uint32_t> sheet_of(through_v_.size(), kNone);  // per root
    std::vector<Sheet<D>> result;
    for (uint32_t root = 0; root < through_v_.size(); ++root)
      if (is_root[root]) sheet_of[root] = static_cast<uint32_t>(result.size()), result.emplace_back();
    for (uint32_t c = 0; c < through_v_.size(); ++c) result[sheet_of[sheets.find(c)]].constraints.push_back(c);
    for (Sheet<D>& sheet : result) {
      if (unbend_)
        for (uint32_t c : sheet.constraints)
          if (!coplanar(sheet.constraints.front(), c)) sheet.bent = true;
      if (!fill(sheet)) return {};
    }
    return result;
  }

  const std::optional<std::string>& refusal() const { return refusal_; }

 private:
  using Ridge = std::array<uint32_t, D - 1>;  // sorted

  Ridge ridge(uint32_t c, int skip) const {
    Ridge r;
    for (int i = 0, j = 0; i < D; ++i)
      if (i != skip) r[j++] = through_v_[c][i];
    std::sort(r.begin(), r.end());
    return r;
  }
  // How many constraints through v hold ridge r.
  std::size_t constraints_on(const Ridge& r) const {
    const auto [first, last] = std::equal_range(ridges_.begin(), ridges_.end(), std::pair<Ridge, uint32_t>{r, 0},
                                                [](const auto& x, const auto& y) { return x.first < y.first; });
    return static_cast<std::size_t>(last - first);
  }
  uint32_t apex(uint32_t c, const Ridge& r) const {
    for (uint32_t x : through_v_[c])
      if (!std::binary_search(r.begin(), r.end(), x)) return x;
    return v_;
  }
  Sign orient_with(uint32_t c, uint32_t x) const {
    predicates::Coords<D + 1> p;
    for (int i = 0; i < D; ++i) p[i] = point_(through_v_[c][i]);
    p[D] = point_(x);
    return predicates::orient<D>(p);
  }
  bool coplanar(uint32_t a, uint32_t b) const {
    for (uint32_t x : through_v_[b])  // a's own vertices are in its hyperplane (and cost an exact zero)
      if (std::find(through_v_[a].begin(), through_v_[a].end(), x) == through_v_[a].end() && orient_with(a, x) != Sign::Zero) return false;
    return true;
  }
  // Two coplanar simplices on ridge r lie on its two sides (one sheet), not folded onto each other.
  bool opposite(uint32_t a, uint32_t b, const Ridge& r) const {
    if constexpr (D == 2) {
      const double *x = point_(r[0]), *p = point_(apex(a, r)), *q = point_(apex(b, r));
      for (int k = 0; k < 2; ++k)
        if (p[k] != x[k]) return (p[k] < x[k]) != (q[k] < x[k]);
      return false;
    } else {
      // In the hyperplane, the apexes are on opposite sides of r iff the simplices are oppositely
      // oriented when written as (r, apex): compare in a projection that keeps the hyperplane's
      // orientation.
      const int k = projection_axis(a);
      return projected_orient(r, apex(a, r), k) == -projected_orient(r, apex(b, r), k);
    }
  }

  // A coordinate axis along which the hyperplane of constraint c projects one-to-one.
  int projection_axis(uint32_t c) const {
    if constexpr (D == 2) {
      return point_(through_v_[c][0])[0] != point_(through_v_[c][1])[0] ? 1 : 0;
    } else {
      for (int k = 0; k < D; ++k)
        if (projected_orient(through_v_[c].data(), through_v_[c][D - 1], k) != Sign::Zero) return k;
      return 0;  // unreachable for a non-degenerate constraint
    }
  }
  std::array<double, D - 1> project(uint32_t x, int axis) const {
    std::array<double, D - 1> p;
    for (int i = 0, j = 0; i < D; ++i)
      if (i != axis) p[j++] = point_(x)[i];
    return p;
  }
  // The orientation of the D - 1 points `ids` and `last` projected along `axis`.
  Sign projected_orient(const uint32_t* ids, uint32_t last, int axis) const {
    predicates::Coords<D> c;
    for (int i = 0; i < D; ++i) c[i] = point_(i + 1 < D ? ids[i] : last);
    return predicates::orient_projected<D>(c, axis);
  }
  Sign projected_orient(const Ridge& ids, uint32_t last, int axis) const { return projected_orient(ids.data(), last, axis); }
  Sign projected_orient(std::initializer_list<uint32_t> ids, uint32_t last, int axis) const { return projected_orient(ids.begin(), last, axis); }

  // Records why v cannot be deleted; false. Most deletion attempts of Steiner points that stay end
  // here (a point rounded off its segment is a corner of its facets), and unwinding an exception
  // cost 6% of a jittered scan's run.
  bool refuse(const Sheet<D>& sheet, const std::string& why) {
    refusal_ = "vertex " + std::to_string(v_) + " cannot be deleted: " + why + " (constraining simplex " +
               ids_text(through_v_[sheet.constraints.front()].data(), D) + ")";
    return false;
  }

  bool fill(Sheet<D>& sheet) {
    // Free ridges: on one simplex of the sheet — the sheet's boundary passes through v there.
    std::vector<Ridge> free, in_sheet;
    for (uint32_t c : sheet.constraints)
      for (int i = 0; i < D; ++i)
        if (through_v_[c][i] != v_) in_sheet.push_back(ridge(c, i));
    std::sort(in_sheet.begin(), in_sheet.end());
    for (std::size_t k = 0, n = 0; k < in_sheet.size(); k += n) {
      n = 1;
      while (k + n < in_sheet.size() && in_sheet[k + n] == in_sheet[k]) ++n;
      if (n == 1) free.push_back(in_sheet[k]);
      else if (constraints_on(in_sheet[k]) != 2) return refuse(sheet, "more than two facets meet at a ridge through it");
    }
    if constexpr (D == 2) {
      if (sheet.constraints.size() != 2) return refuse(sheet, "it is an end of a constraining segment");
      std::array<uint32_t, 2> ab;
      for (int j = 0; j < 2; ++j) {
        const auto& c = through_v_[sheet.constraints[j]];
        ab[j] = c[0] == v_ ? c[1] : c[0];
      }
      sheet.fill.push_back(orient_segment_like(ab, through_v_[sheet.constraints[0]]));  // runs the same way
      return true;
    } else {
      std::optional<Ridge> closing;  // the straight edge through v that the sheet's boundary keeps
      if (!free.empty()) {
        if constexpr (D != 3) {
          return refuse(sheet, "it lies on the boundary of a facet (handled in D = 3 only)");
        } else {
          if (free.size() != 2) return refuse(sheet, "it is a corner of a facet");
          const uint32_t a = free[0][0] == v_ ? free[0][1] : free[0][0];
          const uint32_t b = free[1][0] == v_ ? free[1][1] : free[1][0];
          if (!strictly_inside_segment<D>(point_(a), point_(v_), point_(b))) {
            if (!unbend_) return refuse(sheet, "it is a corner of a facet");
            sheet.bent = true;
          }
          closing = Ridge{std::min(a, b), std::max(a, b)};
        }
      }
      if (!triangulate(sheet, closing)) return false;
      if (unbend_ && !bent_fill_fits(sheet)) return refuse(sheet, "its facet, bent by rounding, would fold over without it");
      return true;
    }
  }

  // A facet bent by rounding is filled in one projection (triangulate), where points nearly on one
  // line turn by rounding. Two things must not come of it:
  // - a triangle of a Steiner point and its two neighbours on its segment (both its sides at it on
  //   the facet's boundary: an ear there is exactly flat in a flat facet and never cut): it lies
  //   along the segment, on the other facet too, folded over;
  // - a triangle facing the other way than the piece it replaces in another projection: `sweepcdt
  //   check` would find its tetrahedron outside. So each must turn like that piece in every
  //   projection where the piece is not thin — the axes of its normal's large components, which
  //   include the one the check projects the input facet along (exact tests; the choice of axes
  //   is only which tests to make). A guard: the slivers of the first rule were the only such
  //   triangles seen (a jittered vase_std: 154 `check` failures before either rule; with the first
  //   alone none there, on 5 more double-coordinate surfaces, or on 15 jittered vases).
  bool bent_fill_fits(const Sheet<D>& sheet) const {
    if constexpr (D == 3) {
      for (const auto& t : sheet.fill)
        for (int i = 0; i < 3; ++i) {
          const uint32_t x = t[(i + 2) % 3], s = t[i], y = t[(i + 1) % 3];
          // ridge(s, ·) looks among s's constraints: a Steiner point has a few, where an input vertex
          // at the apex of a CAD fan has dozens (x first, that scan was a quarter of sheets_without()).
          if (s >= unbend_->first_steiner && unbend_->ridge(s, x) && unbend_->ridge(s, y)) return false;
        }
      const auto& c0 = through_v_[sheet.constraints.front()];
      double n[3];
      for (int k = 0; k < 3; ++k) n[k] = normal_component(point_(c0[0]), point_(c0[1]), point_(c0[2]), k);
      const double largest = std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
      for (int k = 0; k < 3; ++k) {
        if (std::abs(n[k]) < 0.5 * largest) continue;
        const Sign want = projected_orient({c0[0], c0[1]}, c0[2], k);
        if (want == Sign::Zero) continue;
        for (const auto& t : sheet.fill)
          if (projected_orient({t[0], t[1]}, t[2], k) != want) return false;
      }
    }
    return true;
  }
  // The axis of the largest component of constraint c's normal (D = 3) if c projects one-to-one
  // along it (exactly), else projection_axis().
  int dominant_axis(uint32_t c) const {
    if constexpr (D == 3) {
      const auto& t = through_v_[c];
      const int best = detail::dominant_axis(point_(t[0]), point_(t[1]), point_(t[2]));
      if (projected_orient(t.data(), t[D - 1], best) != Sign::Zero) return best;
    }
    return projection_axis(c);
  }

  std::array<uint32_t, 2> orient_segment_like(std::array<uint32_t, 2> ab, const std::array<uint32_t, D>& c0) const {
    // On one line: compare the direction along an axis where c0 has extent (so has ab).
    for (int k = 0; k < D; ++k)
      if (point_(c0[1])[k] != point_(c0[0])[k]) {
        if ((point_(c0[0])[k] < point_(c0[1])[k]) != (point_(ab[0])[k] < point_(ab[1])[k])) std::swap(ab[0], ab[1]);
        break;
      }
    return ab;
  }

  // The (D-1)-dimensional star CDT of the sheet's polytope without v, on its projection.
  bool triangulate(Sheet<D>& sheet, const std::optional<Ridge>& closing) {
    if constexpr (D > 2) {
      const uint32_t c0 = sheet.constraints.front();
      // A sheet bent by rounding is projected along the largest component of its first piece's
      // normal: an axis that only just keeps that piece one-to-one may fold the rest.
      const int axis = unbend_ ? dominant_axis(c0) : projection_axis(c0);
      // The fill is oriented like c0 within the hyperplane: the same sign of the projected orientation.
      const Sign want = projected_orient(through_v_[c0].data(), through_v_[c0][D - 1], axis);
      std::vector<Ridge> boundary;
      for (uint32_t c : sheet.constraints)
        for (int i = 0; i < D; ++i)
          if (through_v_[c][i] == v_) boundary.push_back(ridge(c, i));
      if (closing) boundary.push_back(*closing);
      std::vector<uint32_t> ids;
      for (const auto& r : boundary) ids.insert(ids.end(), r.begin(), r.end());
      std::sort(ids.begin(), ids.end(), [&](uint32_t x, uint32_t y) { return order_(x) < order_(y); });
      ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
      // Half of the holes a Steiner point's deletion leaves in a facet are one triangle (the point
      // had one neighbour inside the facet): that triangle is the hole's only triangulation, so no
      // star CDT, validation or flips are needed. Its three sides are the hole's boundary, two of
      // them edges of triangles through v, so it is not degenerate.
      if constexpr (D == 3)
        if (ids.size() == 3 && boundary.size() == 3 && boundary[0] != boundary[1] && boundary[0] != boundary[2] && boundary[1] != boundary[2]) {
          std::array<uint32_t, D> s{ids[0], ids[1], ids[2]};
          if (projected_orient({s[0], s[1]}, s[2], axis) != want) std::swap(s[0], s[1]);
          sheet.fill.push_back(s);
          return true;
        }
      if constexpr (D == 3)
        if (ids.size() <= kMostEarClipped && triangulate_by_ears(sheet, boundary, v_, axis, want)) return true;
      // A bent sheet's hole may fold in its projection: two of its points, or v and one of them,
      // one point there — no polygon to fill (the sweep needs its edges to span lines).
      if (unbend_) {
        std::vector<std::array<double, D - 1>> projected{project(v_, axis)};
        for (uint32_t x : ids) projected.push_back(project(x, axis));
        std::sort(projected.begin(), projected.end());
        if (std::adjacent_find(projected.begin(), projected.end()) != projected.end())
          return refuse(sheet, "its facet, bent by rounding, folds over in projection without it");
      }
      std::map<uint32_t, uint32_t> local;
      Plc<D - 1> polytope;
      for (uint32_t x : ids) {
        local[x] = static_cast<uint32_t>(polytope.num_points());
        const auto p = project(x, axis);
        polytope.points.insert(polytope.points.end(), p.begin(), p.end());
      }
      const auto centre = project(v_, axis);
      for (const auto& r : boundary) {
        // The polytope lies on v's side of each boundary face; the closing edge passes through v,
        // so there a vertex of the sheet off it tells the side.
        uint32_t inside = v_;
        if (r == closing)
          for (uint32_t c : sheet.constraints)
            if (std::count(through_v_[c].begin(), through_v_[c].end(), r[0]))
              for (uint32_t x : through_v_[c])
                if (x != v_ && x != r[0] && x != r[1]) inside = x;
        const Sign o = projected_orient(r, inside, axis);  // r's first D - 1 vertices, then `inside`
        for (uint32_t x : r) polytope.simplices.push_back(local[x]);
        polytope.exterior.push_back(o == Sign::Positive ? ExteriorSide::Negative : ExteriorSide::Positive);
      }
      // The polytope is valid by construction (a fan around v, less v), so no PLC check; the
      // cavity's validation later checks these simplices again as its constraints.
      Triangulation<D - 1> tri;
      try {
        CdtStatistics stats;
        tri = star_sweep_cdt<D - 1>(polytope, centre, Options{}, stats);
        compute_neighbors(tri);
        if (!validate(tri, polytope).ok()) throw NoCdtError("its star CDT fails validation", {});
      } catch (const NoCdtError& e) {
        return refuse(sheet, std::string("its facet has no CDT without it (") + e.what() + ")");
      }
      for (std::size_t t = 0; t < tri.num_simplices(); ++t) {
        std::array<uint32_t, D> s;
        for (int i = 0; i < D; ++i) s[i] = ids[tri.simplex(t)[i]];
        if (want == Sign::Negative) std::swap(s[0], s[1]);  // star_cdt's simplices are positively oriented
        sheet.fill.push_back(s);
      }
      if constexpr (D == 3) flip_to_in_plane_delaunay(sheet.fill, axis, want);
    }
    return true;
  }

  // A hole of a few vertices (D = 3) is cut into ears along its boundary polygon (`boundary`: its
  // edges; `inside`: a point that sees each of them from inside, v) and flipped to the in-plane CDT:
  // Lawson's flips reach the polygon's one CDT (under the perturbation) from any triangulation, so
  // this is the triangulation the star CDT of the projection, flipped, gives — without the sweep and
  // its validation. False when it does not apply: the boundary is not one cycle, or rounding puts
  // the lifted point of the flips in the plane (then the projection's CDT is kept, below).
  static constexpr std::size_t kMostEarClipped = 12;
  bool triangulate_by_ears(Sheet<D>& sheet, const std::vector<Ridge>& boundary, uint32_t inside, int axis, Sign want) const {
    const std::size_t n = boundary.size();
    std::vector<uint32_t> cycle{boundary[0][0], boundary[0][1]};
    std::vector<char> used(n, 0);
    used[0] = 1;
    for (std::size_t walked = 1; walked < n; ++walked) {
      const uint32_t at = cycle.back();
      std::size_t e = 0;
      while (e < n && (used[e] || (boundary[e][0] != at && boundary[e][1] != at))) ++e;
      if (e == n) return false;
      used[e] = 1;
      cycle.push_back(boundary[e][0] == at ? boundary[e][1] : boundary[e][0]);
    }
    if (cycle.back() != cycle.front()) return false;
    cycle.pop_back();
    std::vector<uint32_t> distinct = cycle;
    std::sort(distinct.begin(), distinct.end());
    if (std::unique(distinct.begin(), distinct.end()) != distinct.end()) return false;
    // Run the cycle with the hole on the `want` side of each edge.
    for (std::size_t i = 0; i < n; ++i) {
      const Sign side = projected_orient({cycle[i], cycle[(i + 1) % n]}, inside, axis);
      if (side == Sign::Zero) continue;  // the closing edge through v
      if (side != want) std::reverse(cycle.begin(), cycle.end());
      break;
    }
    // Ears: a corner turning the `want` way whose triangle holds no other vertex of the polygon.
    const auto off = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t q) {
      return projected_orient({a, b}, q, axis) == -want || projected_orient({b, c}, q, axis) == -want || projected_orient({c, a}, q, axis) == -want;
    };
    std::vector<std::array<uint32_t, D>> ears;
    while (cycle.size() > 3) {
      const std::size_t m = cycle.size();
      std::size_t i = 0;
      for (; i < m; ++i) {
        const uint32_t a = cycle[(i + m - 1) % m], b = cycle[i], c = cycle[(i + 1) % m];
        if (projected_orient({a, b}, c, axis) != want) continue;
        if (std::all_of(cycle.begin(), cycle.end(), [&](uint32_t q) { return q == a || q == b || q == c || off(a, b, c, q); })) break;
      }
      if (i == m) return false;  // a simple polygon always has an ear: only a degenerate walk gets here
      ears.push_back({cycle[(i + m - 1) % m], cycle[i], cycle[(i + 1) % m]});
      cycle.erase(cycle.begin() + static_cast<std::ptrdiff_t>(i));
    }
    if (projected_orient({cycle[0], cycle[1]}, cycle[2], axis) != want) return false;
    ears.push_back({cycle[0], cycle[1], cycle[2]});
    if (!flip_to_in_plane_delaunay(ears, axis, want)) return false;
    sheet.fill.insert(sheet.fill.end(), ears.begin(), ears.end());
    return true;
  }

  // The projection's CDT is a CDT for the projected metric; in a plane oblique to the axes it need
  // not be the facet's own. Lawson's flips make it so: the in-circle test of coplanar points is the
  // insphere test with a point e off their plane (facet_flips.h; e's perturbation term vanishes),
  // under the perturbation order of the points. Flips stay inside the hole (its boundary edges have
  // one triangle) and keep each triangle oriented like the sheet.
  // False, changing nothing, when rounding puts e in the plane (then the caller keeps the
  // projection's CDT, or has none).
  bool flip_to_in_plane_delaunay(std::vector<std::array<uint32_t, D>>& fill, int axis, Sign want) const {
    if (fill.size() < 2) return true;
    const double *a = point_(fill[0][0]), *b = point_(fill[0][1]), *c = point_(fill[0][2]);
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double e[3] = {a[0] + u[1] * w[2] - u[2] * w[1], a[1] + u[2] * w[0] - u[0] * w[2], a[2] + u[0] * w[1] - u[1] * w[0]};
    if (predicates::orient<3>({a, b, c, e}) == Sign::Zero) return false;
    const auto vertex = [&](uint32_t x) { return predicates::Vertex{point_(x), order_(x)}; };
    const auto oriented = [&](uint32_t x, uint32_t y, uint32_t z) { return projected_orient({x, y}, z, axis) == want; };
    struct Side {
      uint64_t edge;  // its two vertices, the smaller first
      uint32_t triangle;
      int apex;  // the slot of the triangle's vertex off the edge
      bool operator<(const Side& o) const { return std::tie(edge, triangle, apex) < std::tie(o.edge, o.triangle, o.apex); }
    };
    std::vector<Side> sides;
    for (std::size_t flips = 0; flips <= fill.size() * fill.size();) {
      sides.clear();
      for (uint32_t t = 0; t < fill.size(); ++t)
        for (int i = 0; i < 3; ++i) {
          const uint32_t x = fill[t][(i + 1) % 3], y = fill[t][(i + 2) % 3];
          sides.push_back({edge_key(x, y), t, i});
        }
      std::sort(sides.begin(), sides.end());
      bool flipped = false;
      for (std::size_t k = 0; k < sides.size(); ++k) {
        // An edge of two triangles (inside the hole); boundary edges have one.
        if (k + 1 == sides.size() || sides[k + 1].edge != sides[k].edge) continue;
        const uint32_t t1 = sides[k].triangle, t2 = sides[k + 1].triangle;
        const int i1 = sides[k].apex, i2 = sides[k + 1].apex;
        ++k;
        const uint32_t x = fill[t1][(i1 + 1) % 3], y = fill[t1][(i1 + 2) % 3], p = fill[t1][i1], q = fill[t2][i2];
        // (x, y, p, e) is a tetrahedron when the fill is flat; a facet bent by rounding (`unbend`)
        // can have a triangle whose plane holds e: then that edge is not flipped.
        if (unbend_ && predicates::orient<3>({point_(x), point_(y), point_(p), e}) == Sign::Zero) continue;
        if (!predicates::inside_circumsphere<3>({vertex(x), vertex(y), vertex(p), {e, kNone - 1}}, vertex(q))) continue;
        if (!oriented(x, q, p) || !oriented(y, p, q)) continue;  // not a convex quadrilateral
        fill[t1] = {x, q, p};
        fill[t2] = {y, p, q};
        flipped = true;
        ++flips;
        break;
      }
      if (!flipped) return true;
    }
    return true;  // past the cap on flips (never reached: Lawson's flips end sooner)
  }

  const uint32_t v_;
  const std::vector<std::array<uint32_t, D>>& through_v_;
  const std::function<const double*(uint32_t)>& point_;
  const std::function<uint32_t(uint32_t)>& order_;
  const std::function<bool(uint32_t, uint32_t)>& same_facet_;
  const Unbend* unbend_;  // sheets_without()'s
  std::vector<std::pair<Ridge, uint32_t>> ridges_;  // run()
  std::optional<std::string> refusal_;
};

}  // namespace

template <int D>
std::vector<Sheet<D>> sheets_without(uint32_t v, const std::vector<std::array<uint32_t, D>>& through_v,
                                     const std::function<const double*(uint32_t)>& point,
                                     const std::function<uint32_t(uint32_t)>& order,
                                     const std::function<bool(uint32_t, uint32_t)>& same_facet, const Unbend* unbend, std::string* refusal) {
  SheetBuilder<D> builder(v, through_v, point, order, same_facet, unbend);
  std::vector<Sheet<D>> sheets = builder.run();
  if (builder.refusal()) {
    if (!refusal) throw VertexRemovalError(*builder.refusal());
    *refusal = *builder.refusal();
  }
  return sheets;
}

#define SWEEPCDT_INSTANTIATE(D)                                                                                       \
  template std::vector<Sheet<D>> sheets_without<D>(uint32_t, const std::vector<std::array<uint32_t, D>>&,                    \
                                                   const std::function<const double*(uint32_t)>&,                            \
                                                   const std::function<uint32_t(uint32_t)>&,                                 \
                                                   const std::function<bool(uint32_t, uint32_t)>&, const Unbend*, std::string*);
SWEEPCDT_INSTANTIATE(2)
SWEEPCDT_INSTANTIATE(3)
SWEEPCDT_INSTANTIATE(4)
SWEEPCDT_INSTANTIATE(5)
#undef SWEEPCDT_INSTANTIATE

}  // namespace sweepcdt::detail
