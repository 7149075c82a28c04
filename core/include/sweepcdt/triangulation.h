// Triangulation<D>: the result of a CDT computation, in flat arrays.
//
//   points:     (n_input + n_steiner) x D. The first num_input_points are the PLC's points, unchanged
//               and in the same order, so vertex ids of the PLC remain valid.
//   steiner_on: per Steiner point (point num_input_points + k), the constraining simplex it was put on,
//               or kNone for a point in the interior of the domain.
//   simplices:  s x (D+1) vertex ids, every simplex positively oriented (orient > 0).
//   neighbors:  s x (D+1): entry (D+1)*t + i is the facet opposite vertex i of simplex t, seen from the
//               other side, encoded as (D+1)*u + j (simplex u, its facet opposite vertex j), or kNone.
//   regions:    s region ids (empty when the caller asked for none).
//   perturbation_rank: empty, or one entry per point: the order of the symbolic perturbation (paper §6)
//               under which the simplices are constrained Delaunay — point v is perturbed as if its
//               id were perturbation_rank[v] (lower = larger perturbation). Empty: by vertex id, the
//               order cdt() always tries first; it sets this only when that order left the PLC
//               without a CDT and a later one of sweepcdt/perturbation_order.h did not. validate()
//               honours it.
//
// Local numbering: facet i of a simplex is the simplex without its vertex i.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace sweepcdt {

inline constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

template <int D>
struct Triangulation {
  static constexpr int dimension = D;

  std::vector<double> points;
  uint32_t num_input_points = 0;
  std::vector<uint32_t> steiner_on;
  std::vector<uint32_t> simplices;
  std::vector<uint32_t> neighbors;
  std::vector<int32_t> regions;
  std::vector<uint32_t> perturbation_rank;

  std::size_t num_points() const { return points.size() / D; }
  std::size_t num_simplices() const { return simplices.size() / (D + 1); }
  const double* point(uint32_t i) const { return points.data() + std::size_t{i} * D; }
  const uint32_t* simplex(std::size_t t) const { return simplices.data() + t * (D + 1); }
};

// A triangulation of the PLC's points (no Steiner points) with the given simplices, no neighbours yet.
template <int D, class Plc>
Triangulation<D> triangulation_of(const Plc& plc, std::vector<uint32_t> simplices) {
  Triangulation<D> tri;
  tri.points = plc.points;
  tri.num_input_points = static_cast<uint32_t>(plc.num_points());
  tri.simplices = std::move(simplices);
  return tri;
}

// Fills tri.neighbors from tri.simplices (facets shared by more than two simplices are left unpaired;
// validate() reports them).
template <int D>
void compute_neighbors(Triangulation<D>& tri);

}  // namespace sweepcdt
