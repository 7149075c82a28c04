// validate(): the oracle that every algorithm of sweepcdt is tested against, and public API.
//
// It decides exactly (through sweepcdt::predicates) whether `tri` is a constrained Delaunay
// triangulation of `plc` (of its perturbed points, paper §6):
//   shape        array sizes agree; perturbation_rank empty or a permutation of the points;
//   topology     ids in range, no repeated ids, every facet in at most two simplices, neighbours
//                symmetric and equal to the facet adjacency;
//   orientation  every simplex strictly positively oriented; at every interior facet the two
//                simplices lie on opposite sides;
//   constraints  every constraining simplex is a facet or is exactly covered by facets (Steiner points
//                on it: equal measure, exact);
//   domain       boundary facets are exactly the domain's boundary: notated constraints with the
//                simplex on the non-exterior side (facet-bounded), or a locally convex closed hull
//                boundary holding every input point (convex hull); the total volume equals the domain's
//                volume computed from its boundary (exact sums); no unused input point lies inside;
//   delaunay     (Full) every interior facet that is not in a constraint is locally Delaunay under the
//                perturbed insphere test — which, with the above, makes every simplex constrained
//                Delaunay; the perturbation is ordered by tri.perturbation_rank when it is set (cdt()
//                tried another order, paper §6), else by vertex id;
//   regions      region ids (if present) agree across facets that are not constraints.
#pragma once
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "sweepcdt/plc.h"
#include "sweepcdt/triangulation.h"

namespace sweepcdt {

enum class ValidationLevel {
  Topology,  // topology, orientation, constraints and domain
  Full,      // ... and the local constrained Delaunay property
};

struct ValidationReport {
  struct Failure {
    std::string check;   // e.g. "orientation", "locally-delaunay"
    std::string detail;  // names the simplices/facets/points involved
  };
  std::vector<Failure> failures;         // the first few of each check
  std::map<std::string, std::size_t> counts;  // how many failures of each check in total

  bool ok() const { return counts.empty(); }
  std::size_t count(const std::string& check) const {
    const auto it = counts.find(check);
    return it == counts.end() ? 0 : it->second;
  }
  std::string summary() const;  // one line per failure, then totals
};

// `threads`: how many threads run the per-simplex and per-facet tests (0: every hardware thread); the
// report is the same for any number.
template <int D>
ValidationReport validate(const Triangulation<D>& tri, const Plc<D>& plc,
                          ValidationLevel level = ValidationLevel::Full, unsigned threads = 0);

}  // namespace sweepcdt
