#include "segment_recovery.h"

#include <algorithm>
#include <array>
#include <string>
#include <unordered_set>

#include "../gift_wrap.h"
#include "../sweep/sweep_cdt.h"

namespace sweepcdt::detail {
namespace {

constexpr int kMaxRounds = 40;
constexpr int kMaxGrowingRounds = 4;     // consecutive rounds with more splits than the one before
constexpr std::size_t kMaxGrowth = 8;    // Steiner points at most 8 x the input points

uint64_t edge_key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t{a} << 32) | b;
}

// The edges of the perturbed Delaunay triangulation of all points (no constraints: sweep sphere).
std::unordered_set<uint64_t> delaunay_edges(const Plc<3>& plc, const Options& options) {
  Plc<3> points;
  points.points = plc.points;
  CdtStatistics stats;
  const Triangulation<3> dt = sweep_cdt<3>(points, seed_simplex(points), options, stats);
  std::unordered_set<uint64_t> edges;
  edges.reserve(dt.num_simplices() * 2);
  for (std::size_t t = 0; t < dt.num_simplices(); ++t) {
    const uint32_t* s = dt.simplex(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert(edge_key(s[i], s[j]));
  }
  return edges;
}

}  // namespace

RefinedPlc recover_segments(const Plc<3>& input, const Options& options) {
  RefinedPlc r;
  r.plc = input;
  r.num_input_points = static_cast<uint32_t>(input.num_points());
  r.original.resize(input.num_simplices());
  for (std::size_t j = 0; j < r.original.size(); ++j) r.original[j] = static_cast<uint32_t>(j);
  if (r.plc.exterior.empty()) r.plc.exterior.assign(input.num_simplices(), ExteriorSide::None);

  std::size_t previous = 0;
  int growing = 0;
  for (;; ++r.rounds) {
    const auto delaunay = delaunay_edges(r.plc, options);
    // Edges of constraining triangles that are not Delaunay, each once.
    std::vector<std::pair<uint32_t, uint32_t>> split;
    std::unordered_set<uint64_t> marked;
    for (std::size_t j = 0; j < r.plc.num_simplices(); ++j) {
      const uint32_t* t = r.plc.simplex(j);
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = t[i], b = t[(i + 1) % 3];
        if (!delaunay.count(edge_key(a, b)) && marked.insert(edge_key(a, b)).second) split.push_back({a, b});
      }
    }
    if (options.progress && !options.progress({"steiner points", split.size(), r.plc.num_points()})) throw CancelledError();
    if (split.empty()) return r;
    // Midpoint splitting can cascade (each split adds a median edge that may not be Delaunay in turn):
    // stop before it eats the memory, with an error that says so.
    growing = split.size() > previous ? growing + 1 : 0;
    previous = split.size();
    const bool over_budget = r.plc.num_points() + split.size() > kMaxGrowth * std::max<std::size_t>(r.num_input_points, 64);
    if (r.rounds == kMaxRounds || growing >= kMaxGrowingRounds || over_budget)
      throw NoCdtError("Steiner points: midpoint splitting does not converge here (" + std::to_string(split.size()) +
                           " segments still not Delaunay after " + std::to_string(r.rounds + 1) + " rounds, " +
                           std::to_string(r.plc.num_points() - r.num_input_points) +
                           " Steiner points); this surface needs the planned refinement with protected vertices",
                       {split.front().first, split.front().second});
    // New midpoints, then every triangle split along each of its split edges in turn.
    std::unordered_map<uint64_t, uint32_t> midpoint;
    for (const auto& [a, b] : split) {
      const uint32_t m = static_cast<uint32_t>(r.plc.num_points());
      for (int k = 0; k < 3; ++k) r.plc.points.push_back(r.plc.point(a)[k] + (r.plc.point(b)[k] - r.plc.point(a)[k]) / 2);
      midpoint.emplace(edge_key(a, b), m);
      r.steiner_on.push_back(kNone);  // filled below from a triangle holding the edge
    }
    std::vector<uint32_t> simplices;
    std::vector<ExteriorSide> exterior;
    std::vector<uint32_t> original;
    std::vector<std::array<uint32_t, 3>> work;
    for (std::size_t j = 0; j < r.plc.num_simplices(); ++j) {
      work.assign(1, {r.plc.simplex(j)[0], r.plc.simplex(j)[1], r.plc.simplex(j)[2]});
      // Split the triangle at each marked edge it has (at most three), keeping its orientation.
      for (std::size_t w = 0; w < work.size(); ++w) {
        for (int i = 0; i < 3; ++i) {
          const uint32_t a = work[w][i], b = work[w][(i + 1) % 3];
          const auto it = midpoint.find(edge_key(a, b));
          if (it == midpoint.end()) continue;
          const uint32_t m = it->second;
          if (r.steiner_on[m - r.num_input_points] == kNone) r.steiner_on[m - r.num_input_points] = r.original[j];
          std::array<uint32_t, 3> first = work[w], second = work[w];
          first[(i + 1) % 3] = m;  // (a, m, c)
          second[i] = m;           // (m, b, c)
          work[w] = first;
          work.push_back(second);
          --w;  // re-examine the shrunken triangle for its other marked edges
          break;
        }
      }
      for (const auto& t : work) {
        simplices.insert(simplices.end(), t.begin(), t.end());
        exterior.push_back(r.plc.exterior[j]);
        original.push_back(r.original[j]);
      }
    }
    r.plc.simplices.swap(simplices);
    r.plc.exterior.swap(exterior);
    r.original.swap(original);
  }
}

}  // namespace sweepcdt::detail
