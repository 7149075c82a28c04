#include "refine.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "delaunay3.h"
#include "facet_flips.h"
#include "facet_groups.h"
#include "sweepcdt/steiner_point.h"

namespace sweepcdt::detail {
namespace {

using Triangle = std::array<uint32_t, 3>;

// Limits that keep a hostile input from running away (the concentric-shell rule terminates, but the
// number of points it needs grows with the ratio of the longest segment to the smallest gap).
constexpr uint64_t kMaxRounds = 200;
std::size_t steiner_budget(std::size_t input_points) { return 20 * input_points + 10000; }

// The edges of the perturbed Delaunay triangulation of the points (no constraints; the incremental
// construction gives the same unique triangulation as the sweep sphere, much faster).
std::unordered_set<uint64_t> delaunay_edges(const std::vector<double>& coordinates) {
  const auto tetrahedra = delaunay_tetrahedra(coordinates);
  std::unordered_set<uint64_t> edges;
  edges.reserve(tetrahedra.size() * 2);
  for (const auto& s : tetrahedra)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert(edge_key(s[i], s[j]));
  return edges;
}

class Refiner {
 public:
  Refiner(const Plc<3>& input, const Options& options)
      : options_(options), groups_(group_facets(input, options.facets)) {
    r_.plc.region_seeds = input.region_seeds;
    r_.num_input_points = static_cast<uint32_t>(input.num_points());
    r_.facets = groups_.num_facets();
    points_ = input.points;
    on_segment_.assign(input.num_points(), {kNone, kNone});
    tris_ = groups_.triangles;
    for (uint32_t j = 0; j < tris_.size(); ++j) original_.push_back(j);
  }

  RefinedPlc run() {
    if (options_.steiner == SteinerMode::Auto) split_until_delaunay();
    std::vector<uint32_t> facet(tris_.size());
    for (std::size_t t = 0; t < tris_.size(); ++t) facet[t] = groups_.facet[original_[t]];
    r_.flips = flip_facets_to_cdt({points_, tris_, facet, groups_.segments, on_segment_});

    r_.plc.points = std::move(points_);
    for (std::size_t t = 0; t < tris_.size(); ++t) {
      r_.plc.simplices.insert(r_.plc.simplices.end(), tris_[t].begin(), tris_[t].end());
      r_.plc.exterior.push_back(groups_.exterior[original_[t]]);
      // A coplanar facet's triangles no longer match input triangles: they carry the facet's first.
      r_.original.push_back(options_.facets == FacetMode::Coplanar ? groups_.first_triangle[facet[t]] : original_[t]);
    }
    return std::move(r_);
  }

 private:
  const double* p(uint32_t v) const { return points_.data() + 3 * std::size_t{v}; }
  bool is_input(uint32_t v) const { return v < r_.num_input_points; }

  void split_until_delaunay() {
    for (;; ++r_.rounds) {
      const auto delaunay = delaunay_edges(points_);
      // Segments that are not Delaunay, each once, in triangle order (deterministic).
      std::vector<uint64_t> split;
      std::unordered_set<uint64_t> marked;
      for (const Triangle& t : tris_)
        for (int i = 0; i < 3; ++i) {
          const uint64_t key = edge_key(t[i], t[(i + 1) % 3]);
          if (groups_.segments.count(key) && !delaunay.count(key) && marked.insert(key).second) split.push_back(key);
        }
      if (options_.progress && !options_.progress({"steiner points", r_.steiner_on.size(), 0})) throw CancelledError();
      if (split.empty()) return;
      if (r_.rounds == kMaxRounds || r_.steiner_on.size() + split.size() > steiner_budget(r_.num_input_points))
        throw NoCdtError("Steiner points: " + std::to_string(split.size()) + " segments still not Delaunay after " +
                             std::to_string(r_.rounds) + " rounds and " + std::to_string(r_.steiner_on.size()) +
                             " Steiner points, over the limit for this input (20 per input point + 10000)",
                         {static_cast<uint32_t>(split.front() >> 32), static_cast<uint32_t>(split.front())});
      std::unordered_map<uint64_t, uint32_t> new_point;
      for (uint64_t key : split) new_point.emplace(key, add_split_point(key));
      split_triangles(new_point);
    }
  }

  // The concentric-shell rule (refine.h): returns the new point's id.
  uint32_t add_split_point(uint64_t key) {
    const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
    double x[3];
    segment_split_point(p(a), is_input(a), p(b), is_input(b), x);  // a < b: edge_key sorts
    if (std::equal(x, x + 3, p(a)) || std::equal(x, x + 3, p(b)))
      throw NoCdtError("Steiner points: a segment is too short to split in double precision", {a, b});
    const uint32_t m = static_cast<uint32_t>(points_.size() / 3);
    points_.insert(points_.end(), x, x + 3);
    on_segment_.push_back(!is_input(a) ? on_segment_[a] : !is_input(b) ? on_segment_[b] : std::array<uint32_t, 2>{a, b});
    r_.steiner_on.push_back(kNone);  // set by split_triangles from a triangle holding the segment
    groups_.segments.erase(key);
    groups_.segments.insert(edge_key(a, m));
    groups_.segments.insert(edge_key(m, b));
    return m;
  }

  // Every triangle split along each of its split edges in turn, keeping its orientation and facet.
  void split_triangles(const std::unordered_map<uint64_t, uint32_t>& new_point) {
    std::vector<Triangle> tris;
    std::vector<uint32_t> original;
    std::vector<Triangle> work;
    for (std::size_t j = 0; j < tris_.size(); ++j) {
      work.assign(1, tris_[j]);
      for (std::size_t w = 0; w < work.size(); ++w)
        for (int i = 0; i < 3; ++i) {
          const auto it = new_point.find(edge_key(work[w][i], work[w][(i + 1) % 3]));
          if (it == new_point.end()) continue;
          const uint32_t m = it->second;
          uint32_t& on = r_.steiner_on[m - r_.num_input_points];
          if (on == kNone) on = original_[j];
          Triangle second = work[w];
          work[w][(i + 1) % 3] = m;  // (a, m, c)
          second[i] = m;             // (m, b, c)
          work.push_back(second);
          --w;  // look at the shrunken triangle again for its other split edges
          break;
        }
      for (const Triangle& t : work) {
        tris.push_back(t);
        original.push_back(original_[j]);
      }
    }
    tris_.swap(tris);
    original_.swap(original);
  }

  const Options& options_;
  FacetGroups groups_;
  RefinedPlc r_;
  std::vector<double> points_;
  std::vector<std::array<uint32_t, 2>> on_segment_;
  std::vector<Triangle> tris_;
  std::vector<uint32_t> original_;  // per triangle: the input triangle it lies in
};

}  // namespace

RefinedPlc refine(const Plc<3>& input, const Options& options) { return Refiner(input, options).run(); }

}  // namespace sweepcdt::detail
