// Plc<D>: a piecewise linear complex in E^D given by its vertices and its constraining
// (D-1)-simplices (paper §1: higher-dimensional facets are first triangulated into simplices).
//
//   points:    n x D doubles, row-major; point i is points[D*i .. D*i+D-1]
//   simplices: m x D vertex ids; simplex j is simplices[D*j .. D*j+D-1]
//   exterior:  empty (the triangulation domain is the convex hull), or m notations saying which side
//              of each simplex is exterior. The "positive side" of simplex (f_0..f_{D-1}) holds the
//              points p with orient(f_0, ..., f_{D-1}, p) > 0. For a closed triangle surface whose
//              triangles are counterclockwise seen from outside, the inside is the positive side, so
//              every triangle is notated ExteriorSide::Negative.
//   region_seeds: optional points naming the region (connected part of the domain) they lie in.
//   tags:      empty, or m caller-defined ids, one per simplex (importers store the index of the input
//              triangle each simplex came from, so outputs can carry face ids / patch tags).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sweepcdt/error.h"

namespace sweepcdt {

enum class ExteriorSide : uint8_t {
  None,      // the domain is on both sides (or the domain is the convex hull)
  Positive,  // the positive side is exterior
  Negative,  // the negative side is exterior
};

template <int D>
struct RegionSeed {
  std::array<double, D> point;
  int32_t region;
};

template <int D>
struct Plc {
  static constexpr int dimension = D;

  std::vector<double> points;
  std::vector<uint32_t> simplices;
  std::vector<ExteriorSide> exterior;
  std::vector<RegionSeed<D>> region_seeds;
  std::vector<uint32_t> tags;

  std::size_t num_points() const { return points.size() / D; }
  std::size_t num_simplices() const { return simplices.size() / D; }
  const double* point(uint32_t i) const { return points.data() + std::size_t{i} * D; }
  const uint32_t* simplex(std::size_t j) const { return simplices.data() + j * D; }
  ExteriorSide exterior_of(std::size_t j) const { return exterior.empty() ? ExteriorSide::None : exterior[j]; }
  // True when some simplex bears an exterior notation: the domain is bounded by facets, not the hull.
  bool facet_bounded() const;
};

// Every problem of the PLC, up to `limit_per_kind` reported per kind (all are counted). Exact: no
// tolerance anywhere. Intersections are found with a bounding-box tree, in O(m log m) for surfaces.
template <int D>
std::vector<PlcProblem> find_problems(const Plc<D>& plc, std::size_t limit_per_kind = 10,
                                      uint64_t* total = nullptr);

// Throws PlcError listing the problems if there are any.
template <int D>
void check(const Plc<D>& plc);

}  // namespace sweepcdt
