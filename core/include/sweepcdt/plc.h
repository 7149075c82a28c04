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
//   checked:   empty, or the record of an earlier find_problems() that found no problem (PlcCheck,
//              below). Set by importers that have checked the surface already (io::to_plc); users
//              never need to touch it. It only ever saves time: a record that does not match the
//              points and simplices bit for bit is ignored and the PLC is checked in full.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "sweepcdt/error.h"

namespace sweepcdt {

enum class ExteriorSide : uint8_t {
  None,      // the domain is on both sides (or the domain is the convex hull)
  Positive,  // the positive side is exterior
  Negative,  // the negative side is exterior
};

template <int D>
class PlcCheck;

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
  std::shared_ptr<const PlcCheck<D>> checked;

  std::size_t num_points() const { return points.size() / D; }
  std::size_t num_simplices() const { return simplices.size() / D; }
  const double* point(uint32_t i) const { return points.data() + std::size_t{i} * D; }
  const uint32_t* simplex(std::size_t j) const { return simplices.data() + j * D; }
  ExteriorSide exterior_of(std::size_t j) const { return exterior.empty() ? ExteriorSide::None : exterior[j]; }
  // True when some simplex bears an exterior notation: the domain is bounded by facets, not the hull.
  bool facet_bounded() const;
};

// The record that find_problems() found no problem at all in a PLC with exactly these points and
// simplices (a copy of both, so that the record cannot outlive a change). Only find_problems()
// makes one. find_problems() of a PLC that carries a record covering it (Plc::checked) skips the
// geometric checks — duplicate points, degenerate and duplicate simplices, intersections, points on
// simplices — whose answer the record already holds, and still checks the rest (shapes, finiteness,
// index ranges, repeated vertices, exterior/tags sizes, region seeds), which costs O(n + m).
// The CAD parts of the README spend about a quarter of their time in the intersection tests: an
// importer that checked the surface passes the record on so that cdt() does not test it again.
namespace detail {
struct KeptTetrahedralization;  // core/src/delaunay/kept_tetrahedralization.h
struct PlcCheckAccess;
}  // namespace detail

template <int D>
class PlcCheck {
 public:
  // True when `plc` has exactly the points (bit for bit) and simplices of the PLC checked.
  bool covers(const Plc<D>& plc) const;

 private:
  friend struct detail::PlcCheckAccess;
  PlcCheck(std::vector<double> points, std::vector<uint32_t> simplices, std::shared_ptr<detail::KeptTetrahedralization> kept)
      : points_(std::move(points)), simplices_(std::move(simplices)), kept_(std::move(kept)) {}
  std::vector<double> points_;
  std::vector<uint32_t> simplices_;
  // find_problems_before_cdt(): the Delaunay tetrahedralization of the points, for cdt() to take.
  std::shared_ptr<detail::KeptTetrahedralization> kept_;
};

// Every problem of the PLC, up to `limit_per_kind` reported per kind (all are counted). Exact: no
// tolerance anywhere. Intersections are found with a bounding-box tree, in O(m log m) for surfaces.
// When there is no problem and `record` is given, *record is set to a PlcCheck of this PLC (else reset).
// `threads`: how many threads test intersections (0: every hardware thread); the answer, down to the
// order of the problems, is the same for any number.
template <int D>
std::vector<PlcProblem> find_problems(const Plc<D>& plc, std::size_t limit_per_kind = 10,
                                      uint64_t* total = nullptr, std::shared_ptr<const PlcCheck<D>>* record = nullptr,
                                      unsigned threads = 0);

// find_problems() of a 3D PLC about to be tetrahedralized (io's importers): given a second thread,
// the Delaunay tetrahedralization of its points is computed there while the checks run on the
// others, and the record keeps it for cdt(), which would otherwise compute it after the check (on a
// small flat CAD part each is about a third of the run). The problems and the answer are those of
// find_problems(); a record that cdt() never uses stops the computation when it is destroyed.
std::vector<PlcProblem> find_problems_before_cdt(const Plc<3>& plc, std::size_t limit_per_kind = 10, uint64_t* total = nullptr,
                                                 std::shared_ptr<const PlcCheck<3>>* record = nullptr, unsigned threads = 0);

// Throws PlcError listing the problems if there are any.
template <int D>
void check(const Plc<D>& plc, unsigned threads = 0);

}  // namespace sweepcdt
