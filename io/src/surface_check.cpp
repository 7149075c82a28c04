// inspect(): is the welded surface the boundary of a volume? Combinatorics first (degenerate and
// duplicate triangles, edges with one or more than two triangles, pinched vertices, orientability),
// then exact geometry (collinear corners, self-intersections via core's find_problems), then, for a
// valid surface, the nesting of its shells and the orientation each one needs.
#include <algorithm>
#include <numeric>
#include <tuple>

#include "nesting.h"
#include "sweepcdt/io/surface.h"
#include "sweepcdt/plc.h"
#include "sweepcdt/predicates/orientation.h"

namespace sweepcdt::io {
namespace {

using predicates::Sign;
std::string n(uint64_t i) { return std::to_string(i); }

class UnionFind {
 public:
  explicit UnionFind(std::size_t size) : parent_(size) { std::iota(parent_.begin(), parent_.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // smallest index as the root
  }

 private:
  std::vector<uint32_t> parent_;
};

// An edge use: triangle t traverses its edge (lo, hi) forward (lo -> hi) or backward.
struct EdgeUse {
  uint32_t lo, hi, triangle;
  uint8_t corner;  // the edge runs from corner to corner + 1 (mod 3)
  bool forward;
};

class Inspector {
 public:
  Inspector(const Surface& s, std::size_t limit, bool before_cdt) : s_(s), limit_(limit), before_cdt_(before_cdt), m_(s.num_triangles()) {
    r_.file = s.file;
    r_.format = s.format;
    r_.triangles = m_;
    r_.points_in_file = s.points_in_file;
    r_.points = s.num_points();
  }

  SurfaceReport run() {
    compute_box();
    find_degenerate_and_duplicates();
    collect_edges();
    check_edges_and_orientation();
    check_vertices();
    find_self_intersections();
    r_.closed = r_.count(SurfaceProblemKind::BoundaryEdge) == 0 && r_.count(SurfaceProblemKind::NonManifoldEdge) == 0 &&
                !index_degenerate_;
    r_.manifold = r_.count(SurfaceProblemKind::NonManifoldEdge) == 0 && r_.count(SurfaceProblemKind::NonManifoldVertex) == 0;
    if (r_.valid()) orient_by_nesting();
    return std::move(r_);
  }

 private:
  const uint32_t* tri(std::size_t t) const { return s_.triangles.data() + 3 * t; }
  const double* point(uint32_t v) const { return s_.points.data() + 3 * std::size_t{v}; }
  void add(SurfaceProblemKind kind, std::vector<uint64_t> elements, std::string message) {
    if (r_.counts[static_cast<int>(kind)]++ < limit_) r_.problems.push_back({kind, std::move(elements), std::move(message)});
  }
  std::string corners(std::size_t t) const { return "(" + n(tri(t)[0]) + ", " + n(tri(t)[1]) + ", " + n(tri(t)[2]) + ")"; }

  void compute_box() {
    if (s_.points.empty()) return;
    r_.box_min = r_.box_max = {s_.points[0], s_.points[1], s_.points[2]};
    for (std::size_t i = 0; i < s_.points.size(); ++i) {
      r_.box_min[i % 3] = std::min(r_.box_min[i % 3], s_.points[i]);
      r_.box_max[i % 3] = std::max(r_.box_max[i % 3], s_.points[i]);
    }
  }

  void find_degenerate_and_duplicates() {
    usable_.assign(m_, 1);
    named_twice_.assign(m_, 0);
    std::vector<std::pair<std::array<uint32_t, 3>, uint32_t>> keys;
    keys.reserve(m_);
    for (uint32_t t = 0; t < m_; ++t) {
      std::array<uint32_t, 3> k{tri(t)[0], tri(t)[1], tri(t)[2]};
      std::sort(k.begin(), k.end());
      if (k[0] == k[1] || k[1] == k[2]) {
        add(SurfaceProblemKind::DegenerateTriangle, {t}, "triangle " + n(t) + " " + corners(t) + " names a vertex twice");
        usable_[t] = 0;
        named_twice_[t] = 1;
        index_degenerate_ = true;
        continue;
      }
      const double *a = point(k[0]), *b = point(k[1]), *c = point(k[2]);
      bool collinear = true;
      for (int drop = 0; drop < 3 && collinear; ++drop) collinear = predicates::orient_projected<3>({a, b, c}, drop) == Sign::Zero;
      if (collinear) {
        add(SurfaceProblemKind::DegenerateTriangle, {t}, "triangle " + n(t) + " " + corners(t) + " has collinear corners (zero area)");
        usable_[t] = 0;
      }
      keys.push_back({k, t});
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i)
      if (keys[i].first == keys[i - 1].first) {
        std::size_t first = i - 1;
        while (first > 0 && keys[first - 1].first == keys[i].first) --first;
        const uint32_t t0 = keys[first].second, t = keys[i].second;
        add(SurfaceProblemKind::DuplicateTriangle, {t0, t}, "triangles " + n(t0) + " and " + n(t) + " have the same vertices " + corners(t));
        usable_[t] = 0;
      }
  }

  // Every edge use of every triangle with three distinct vertices, grouped by edge.
  void collect_edges() {
    uses_.reserve(3 * m_);
    for (uint32_t t = 0; t < m_; ++t) {
      if (named_twice_[t]) continue;
      for (uint8_t c = 0; c < 3; ++c) {
        const uint32_t u = tri(t)[c], v = tri(t)[(c + 1) % 3];
        uses_.push_back({std::min(u, v), std::max(u, v), t, c, u < v});
      }
    }
    // In (lo, hi, triangle, corner) order: a counting sort by lo, then each bucket (the uses at one
    // vertex, a handful on most surfaces) sorted alone — linear in all but the largest fans, where one
    // sort of the 3.9M uses of 1.3M triangles was a twentieth of reading and checking them. The order
    // is total, so the result is the one sort's.
    uint32_t buckets = 0;
    for (const EdgeUse& e : uses_) buckets = std::max(buckets, e.lo + 1);
    std::vector<uint32_t> start(std::size_t{buckets} + 1, 0);
    for (const EdgeUse& e : uses_) ++start[e.lo + 1];
    for (uint32_t v = 0; v < buckets; ++v) start[v + 1] += start[v];
    std::vector<EdgeUse> sorted(uses_.size());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (const EdgeUse& e : uses_) sorted[fill[e.lo]++] = e;
    for (uint32_t v = 0; v < buckets; ++v)
      std::sort(sorted.begin() + start[v], sorted.begin() + start[v + 1], [](const EdgeUse& x, const EdgeUse& y) {
        return std::tie(x.hi, x.triangle, x.corner) < std::tie(y.hi, y.triangle, y.corner);
      });
    uses_.swap(sorted);
  }

  template <class F>
  void for_each_edge(F&& f) const {
    for (std::size_t i = 0, j; i < uses_.size(); i = j) {
      for (j = i + 1; j < uses_.size() && uses_[j].lo == uses_[i].lo && uses_[j].hi == uses_[i].hi;) ++j;
      f(i, j);
    }
  }

  void check_edges_and_orientation() {
    UnionFind components(m_);
    r_.oriented = true;
    // Manifold neighbours, with whether the pair agrees in orientation.
    neighbours_.assign(m_, {});
    for_each_edge([&](std::size_t i, std::size_t j) {
      const EdgeUse& e = uses_[i];
      if (j - i == 1) {
        add(SurfaceProblemKind::BoundaryEdge, {e.lo, e.hi}, "edge (" + n(e.lo) + ", " + n(e.hi) + ") has only triangle " + n(e.triangle) + ": the surface is open");
        open_.push_back(e.triangle);
      } else if (j - i > 2) {
        std::string list;
        for (std::size_t k = i; k < j && k < i + 6; ++k) list += (k > i ? ", " : "") + n(uses_[k].triangle);
        add(SurfaceProblemKind::NonManifoldEdge, {e.lo, e.hi}, "edge (" + n(e.lo) + ", " + n(e.hi) + ") has " + n(j - i) + " triangles: " + list + (j - i > 6 ? ", ..." : ""));
        for (std::size_t k = i; k < j; ++k) open_.push_back(uses_[k].triangle);
      } else {
        const bool agree = uses_[i].forward != uses_[i + 1].forward;
        if (!agree) r_.oriented = false;
        neighbours_[uses_[i].triangle].emplace_back(uses_[i + 1].triangle, agree);
        neighbours_[uses_[i + 1].triangle].emplace_back(uses_[i].triangle, agree);
      }
    });
    // Shells: components through shared vertices (so a pinch joins two shells, as in MANIFEST.md's
    // count); triangles naming a vertex twice belong to none.
    std::vector<uint32_t> first_at(s_.num_points(), UINT32_MAX);
    for (uint32_t t = 0; t < m_; ++t) {
      if (named_twice_[t]) continue;
      for (int c = 0; c < 3; ++c) {
        uint32_t& first = first_at[tri(t)[c]];
        if (first == UINT32_MAX) first = t;
        else components.unite(first, t);
      }
    }
    std::vector<int32_t> shell_of_root(m_, -1);
    shell_of_.assign(m_, -1);
    for (uint32_t t = 0; t < m_; ++t) {
      if (named_twice_[t]) continue;
      const uint32_t root = components.find(t);
      if (shell_of_root[root] < 0) {
        shell_of_root[root] = static_cast<int32_t>(r_.shells.size());
        r_.shells.push_back({t, 0, true});
        shell_triangles_.emplace_back();
      }
      shell_of_[t] = shell_of_root[root];
      ++r_.shells[shell_of_[t]].triangles;
      shell_triangles_[shell_of_[t]].push_back(t);
    }
    for (uint32_t t : open_) r_.shells[shell_of_[t]].closed = false;
    // Orientability: propagate a flip bit through manifold edges; a contradiction means the shell
    // is non-orientable (a Möbius-like band) and no orientation repair exists.
    flip_.assign(m_, 0);
    std::vector<uint8_t> seen(m_, 0);
    std::vector<uint32_t> stack;
    for (const Shell& shell : r_.shells) {
      bool conflict_reported = false;
      seen[shell.first_triangle] = 1;
      stack.assign(1, shell.first_triangle);
      while (!stack.empty()) {
        const uint32_t t = stack.back();
        stack.pop_back();
        for (const auto& [u, agree] : neighbours_[t]) {
          const uint8_t want = agree ? flip_[t] : !flip_[t];
          if (!seen[u]) {
            seen[u] = 1;
            flip_[u] = want;
            stack.push_back(u);
          } else if (flip_[u] != want && !conflict_reported) {
            add(SurfaceProblemKind::NonOrientable, {t, u}, "the shell of triangle " + n(shell.first_triangle) + " cannot be oriented consistently (triangles " + n(t) + " and " + n(u) + " conflict)");
            conflict_reported = true;
          }
        }
      }
    }
  }

  // A vertex is manifold iff its corners form one fan through manifold edges.
  void check_vertices() {
    UnionFind fans(3 * m_);  // corner 3t + c
    auto corner_of = [&](uint32_t t, uint32_t v) {
      for (uint32_t c = 0; c < 3; ++c)
        if (tri(t)[c] == v) return 3 * t + c;
      return 3 * t;
    };
    for_each_edge([&](std::size_t i, std::size_t j) {
      if (j - i != 2) return;
      const uint32_t a = uses_[i].triangle, b = uses_[i + 1].triangle;
      for (uint32_t v : {uses_[i].lo, uses_[i].hi}) fans.unite(corner_of(a, v), corner_of(b, v));
    });
    std::vector<uint32_t> first_fan(s_.num_points(), UINT32_MAX);
    std::vector<uint8_t> reported(s_.num_points(), 0);
    for (uint32_t t = 0; t < m_; ++t) {
      if (named_twice_[t]) continue;
      for (uint32_t c = 0; c < 3; ++c) {
        const uint32_t v = tri(t)[c], fan = fans.find(3 * t + c);
        if (first_fan[v] == UINT32_MAX) first_fan[v] = fan;
        else if (first_fan[v] != fan && !reported[v]) {
          reported[v] = 1;
          add(SurfaceProblemKind::NonManifoldVertex, {v}, "vertex " + n(v) + " is a pinch: its triangles form more than one fan (e.g. triangles " + n(fan / 3) + " and " + n(first_fan[v] / 3) + ")");
        }
      }
    }
  }

  // Exact intersection tests of core's find_problems on the usable triangles only, over only the
  // points they use, so that every problem it reports is an intersecting pair.
  void find_self_intersections() {
    Plc<3> plc;
    std::vector<uint32_t> triangle_of;
    std::vector<uint32_t> id(s_.num_points(), UINT32_MAX);
    for (uint32_t t = 0; t < m_; ++t) {
      if (!usable_[t]) continue;
      for (int c = 0; c < 3; ++c) {
        uint32_t& v = id[tri(t)[c]];
        if (v == UINT32_MAX) {
          v = static_cast<uint32_t>(plc.num_points());
          plc.points.insert(plc.points.end(), point(tri(t)[c]), point(tri(t)[c]) + 3);
        }
        plc.simplices.push_back(v);
      }
      triangle_of.push_back(t);
    }
    uint64_t total = 0;
    // With every triangle usable, plc has the surface's points and triangles in the same order (weld()
    // numbers points by first use), so the record covers to_plc()'s PLC.
    const auto problems =
        before_cdt_ ? find_problems_before_cdt(plc, limit_, &total, &r_.checked) : find_problems(plc, limit_, &total, &r_.checked);
    for (const auto& p : problems) {
      // Distinct points, all used, no degenerate or duplicate simplex: only intersections remain.
      if (p.kind != PlcProblemKind::Intersection) continue;
      const uint32_t a = triangle_of[p.elements[0]], b = triangle_of[p.elements[1]];
      add(SurfaceProblemKind::SelfIntersection, {a, b}, "triangles " + n(a) + " " + corners(a) + " and " + n(b) + " " + corners(b) + " intersect");
    }
    r_.counts[static_cast<int>(SurfaceProblemKind::SelfIntersection)] = total;
    r_.self_intersections_checked = true;
  }

  void orient_by_nesting() {
    detail::nest_shells(s_, shell_triangles_, r_.shells);
    r_.reverse.assign(m_, 0);
    for (std::size_t i = 0; i < r_.shells.size(); ++i) {
      Shell& shell = r_.shells[i];
      // With the flips, the shell is consistently oriented; outward iff its volume is positive.
      const bool outward = detail::volume_sign(s_, shell_triangles_[i], flip_) > 0;
      const bool want_outward = shell.depth % 2 == 0;
      for (uint32_t t : shell_triangles_[i]) r_.reverse[t] = outward == want_outward ? flip_[t] : !flip_[t];
      for (uint32_t t : shell_triangles_[i]) {
        r_.reversed_triangles += r_.reverse[t];
        shell.reversed = shell.reversed || r_.reverse[t];
      }
    }
  }

  const Surface& s_;
  std::size_t limit_;
  bool before_cdt_;  // inspect()
  uint32_t m_;
  SurfaceReport r_;
  std::vector<uint8_t> usable_, named_twice_, flip_;
  bool index_degenerate_ = false;
  std::vector<EdgeUse> uses_;
  std::vector<std::vector<std::pair<uint32_t, bool>>> neighbours_;
  std::vector<uint32_t> open_;
  std::vector<int32_t> shell_of_;
  std::vector<std::vector<uint32_t>> shell_triangles_;
};

}  // namespace

uint64_t SurfaceReport::closed_shells() const {
  return static_cast<uint64_t>(std::count_if(shells.begin(), shells.end(), [](const Shell& s) { return s.closed; }));
}

uint64_t SurfaceReport::nested_shells() const {
  return static_cast<uint64_t>(std::count_if(shells.begin(), shells.end(), [](const Shell& s) { return s.depth > 0; }));
}

bool SurfaceReport::valid() const {
  return triangles > 0 && self_intersections_checked &&
         std::all_of(counts.begin(), counts.end(), [](uint64_t c) { return c == 0; });
}

void SurfaceReport::throw_if_invalid() const {
  if (valid()) return;
  if (triangles == 0) throw SurfaceError(file, {}, std::vector<uint64_t>(kSurfaceProblemKinds, 0));
  throw SurfaceError(file, problems, std::vector<uint64_t>(counts.begin(), counts.end()));
}

SurfaceReport inspect(const Surface& surface, std::size_t limit_per_kind, bool before_cdt) {
  if (surface.num_triangles() >= UINT32_MAX) throw Error(surface.file + ": more than 2^32 - 1 triangles");
  return Inspector(surface, limit_per_kind, before_cdt).run();
}

}  // namespace sweepcdt::io
