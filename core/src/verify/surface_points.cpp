#include "surface_points.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "../box_tree.h"
#include "../segment_interior.h"
#include "split_of_two.h"
#include "sweepcdt/predicates.h"
#include "sweepcdt/steiner_point.h"

namespace sweepcdt::detail {
namespace {

// The box of points given by ids into `points` (n x 3).
Box<3> box_of(std::span<const double> points, const std::vector<uint32_t>& ids) {
  Box<3> b;
  for (int c = 0; c < 3; ++c) b.lo[c] = b.hi[c] = points[3 * std::size_t{ids.front()} + c];
  for (uint32_t v : ids)
    for (int c = 0; c < 3; ++c) {
      b.lo[c] = std::min(b.lo[c], points[3 * std::size_t{v} + c]);
      b.hi[c] = std::max(b.hi[c], points[3 * std::size_t{v} + c]);
    }
  return b;
}

class Splits {
 public:
  explicit Splits(std::span<const double> points) : points_(points) {}
  const double* p(uint32_t v) const { return points_.data() + 3 * std::size_t{v}; }

  // Is s a point that refine can make on the segment ab: the rounded a + t (b - a), or b + t (a - b),
  // for some t in (0, 1)? Exact (sweepcdt/steiner_point.h).
  bool is_split(uint32_t s, uint32_t a, uint32_t b) const { return is_point_on_segment(p(a), p(b), p(s)); }

  // Where split s of a ridge's ends goes among the ridge's points so far (`line`, from one end to
  // the other): after line[i], the returned i. Rounding is monotone, so the splits of one segment
  // are ordered alike in every coordinate (each the way the segment runs): compared coordinate by
  // coordinate, the first that differs orders two of them.
  std::size_t place_on(const std::vector<uint32_t>& line, uint32_t s) const {
    const double* a = p(line.front());
    const double* b = p(line.back());
    const auto before = [&](uint32_t x, uint32_t y) {  // x nearer a than y
      for (int k = 0; k < 3; ++k)
        if (p(x)[k] != p(y)[k]) return (p(x)[k] < p(y)[k]) == (a[k] < b[k]);
      return false;
    };
    std::size_t i = 0;
    while (i + 2 < line.size() && before(line[i + 1], s)) ++i;
    return i;
  }

 private:
  std::span<const double> points_;
};

// Fold points: is s the split of two points placed on facet f so far? is_split_of_two() answers
// exactly in O(k log k) for the facet's k points — for every fold point of a facet that is still
// quadratic overall. So the points of f nearest s are tried first, found with a BoxTree of all
// the mesh's points in boxes around s growing fourfold: refine splits a fold between the ends of
// a current edge (core/src/steiner/refine.cpp, add_split_point), which usually have few points of
// the facet placed before s nearer than they are. A pair among them settles it, being two points
// of f; only when none splits s (and always for a facet whose box holds s but which s is not on)
// are all of f's points searched, so the answer is is_split_of_two() of all of them.
class FoldSearch {
 public:
  explicit FoldSearch(std::span<const double> points) : points_(points) {}

  bool splits_two_of(uint32_t s, uint32_t f, const SurfacePoints& r, const Box<3>& facet_box) {
    if (!tree_) tree_.emplace(point_boxes());  // only meshes with fold points need it
    const double* ps = points_.data() + 3 * std::size_t{s};
    double extent = 0;
    for (int c = 0; c < 3; ++c) extent = std::max(extent, facet_box.hi[c] - facet_box.lo[c]);
    std::size_t tried = 0;
    for (double half = std::ldexp(extent, -16); half < extent; half *= 4) {
      Box<3> around;
      for (int c = 0; c < 3; ++c) around.lo[c] = ps[c] - half, around.hi[c] = ps[c] + half;
      nearby_.clear();
      tree_->for_each_overlap(around, [&](uint32_t w) {
        if (w < s && std::binary_search(r.facets_of[w].begin(), r.facets_of[w].end(), f)) nearby_.push_back(w);
      });
      if (nearby_.size() > kMostNearby) break;
      if (nearby_.size() > tried && nearby_.size() >= 2) {
        tried = nearby_.size();
        if (is_split_of_two(points_, s, nearby_)) return true;
      }
    }
    return is_split_of_two(points_, s, r.on_facet[f]);
  }

 private:
  static constexpr std::size_t kMostNearby = 512;  // beyond this many, search the whole facet

  std::vector<Box<3>> point_boxes() const {
    std::vector<Box<3>> boxes(points_.size() / 3);
    for (std::size_t v = 0; v < boxes.size(); ++v)
      for (int c = 0; c < 3; ++c) boxes[v].lo[c] = boxes[v].hi[c] = points_[3 * v + c];
    return boxes;
  }

  std::span<const double> points_;
  std::optional<BoxTree<3>> tree_;
  std::vector<uint32_t> nearby_;
};

}  // namespace

SurfacePoints locate_points(const Plc<3>& input, const SurfaceFacets& facets, std::span<const double> points, Problems& problems) {
  const uint32_t n = static_cast<uint32_t>(input.num_points()), total = static_cast<uint32_t>(points.size() / 3);
  SurfacePoints r;
  r.on_edge.resize(facets.edges.size());
  r.on_facet.resize(facets.num_facets());
  r.facets_of.resize(total);
  r.off_facet.assign(facets.num_facets(), 0);
  std::vector<uint32_t> ridges;
  std::vector<Box<3>> ridge_boxes, facet_boxes;
  for (uint32_t e = 0; e < facets.edges.size(); ++e) {
    r.on_edge[e] = {facets.edges[e].a, facets.edges[e].b};
    if (!facets.edges[e].ridge) continue;
    ridges.push_back(e);
    ridge_boxes.push_back(box_of(points, r.on_edge[e]));
  }
  for (uint32_t f = 0; f < facets.num_facets(); ++f) {
    auto& on = r.on_facet[f];
    for (uint32_t j : facets.triangles[f]) on.insert(on.end(), input.simplex(j), input.simplex(j) + 3);
    std::sort(on.begin(), on.end());
    on.erase(std::unique(on.begin(), on.end()), on.end());
    for (uint32_t v : on) r.facets_of[v].push_back(f);
    facet_boxes.push_back(box_of(points, on));
  }
  if (total == n) return r;  // no Steiner point to place
  const BoxTree<3> ridge_tree(std::move(ridge_boxes)), facet_tree(std::move(facet_boxes));
  const Splits splits(points);
  FoldSearch folds(points);

  for (uint32_t s = n; s < total; ++s) {
    const double* ps = splits.p(s);
    const Box<3> at{{ps[0], ps[1], ps[2]}, {ps[0], ps[1], ps[2]}};
    auto& on = r.facets_of[s];
    bool exactly_on_segment = false;
    ridge_tree.any_overlap(at, [&](uint32_t k) {
      auto& line = r.on_edge[ridges[k]];
      std::size_t i = 0;
      if (splits.is_split(s, line.front(), line.back())) {
        i = splits.place_on(line, s);
      } else {  // a split of two neighbouring points (surface_points.h)
        while (i + 1 < line.size() && !splits.is_split(s, line[i], line[i + 1])) ++i;
        if (i + 1 == line.size()) return false;
      }
      line.insert(line.begin() + static_cast<std::ptrdiff_t>(i) + 1, s);
      for (uint32_t j : facets.edges[ridges[k]].triangles) on.push_back(facets.facet_of[j]);
      exactly_on_segment = strictly_inside_segment<3>(splits.p(line.front()), ps, splits.p(line.back()));
      return true;
    });
    if (on.empty())  // a fold point
      facet_tree.for_each_overlap(at, [&](uint32_t f) {
        if (folds.splits_two_of(s, f, r, facet_tree.box(f))) on.push_back(f);
      });
    std::sort(on.begin(), on.end());
    on.erase(std::unique(on.begin(), on.end()), on.end());
    if (on.empty()) {
      problems.add("Steiner point " + std::to_string(s) + " " + point_text(ps) + " is not a rounded point of the segment of " +
                   (facets.mode == FacetMode::Triangles ? "an input edge, nor between two points of one input triangle"
                                                        : "a facet's boundary edge, nor between two points of one facet"));
      continue;
    }
    for (uint32_t f : on) {
      r.on_facet[f].push_back(s);
      if (!exactly_on_segment) r.off_facet[f] = 1;
    }
    const uint32_t* t = input.simplex(facets.first_triangle(on.front()));
    if (predicates::orient<3>({input.point(t[0]), input.point(t[1]), input.point(t[2]), ps}) == predicates::Sign::Zero) ++r.exactly_on;
  }
  return r;
}

}  // namespace sweepcdt::detail
