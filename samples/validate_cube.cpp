// Sample: check a PLC (the unit cube's surface as a facet-bounded domain) and validate a
// tetrahedralization of it — the foundation every sweepcdt algorithm is verified with.
//
//   build/samples/validate_cube
//
// It prints what check() and validate() say about a correct tetrahedralization (the cube cut into
// six tetrahedra around its main diagonal, a Delaunay triangulation of its eight cospherical
// vertices only up to the perturbation of paper §6) and about two broken ones.
#include <cstdio>

#include "sweepcdt/plc.h"
#include "sweepcdt/validate.h"

using namespace sweepcdt;

namespace {

Plc<3> cube_surface() {
  Plc<3> plc;
  for (int i = 0; i < 8; ++i) plc.points.insert(plc.points.end(), {double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  // Counterclockwise seen from outside, each face split along the diagonal through vertex 0 or 7.
  plc.simplices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                   2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  plc.exterior.assign(12, ExteriorSide::Negative);  // the inside is every triangle's positive side
  return plc;
}

void report(const char* what, const ValidationReport& r) {
  std::printf("%s: %s\n", what, r.ok() ? "passes" : "FAILS");
  if (!r.ok()) std::printf("%s", r.summary().c_str());
}

}  // namespace

int main() {
  const Plc<3> plc = cube_surface();
  check(plc);  // throws PlcError naming the problem if the PLC were invalid
  std::printf("PLC: %zu points, %zu constraining triangles, facet-bounded: %s\n", plc.num_points(),
              plc.num_simplices(), plc.facet_bounded() ? "yes" : "no");

  Triangulation<3> tri;
  tri.points = plc.points;
  tri.num_input_points = 8;
  // Six tetrahedra around the diagonal 0-7 (the Kuhn triangulation), positively oriented.
  tri.simplices = {0, 1, 3, 7, 0, 3, 2, 7, 0, 2, 6, 7, 0, 6, 4, 7, 0, 4, 5, 7, 0, 5, 1, 7};
  for (std::size_t t = 0; t < 6; ++t) std::swap(tri.simplices[4 * t], tri.simplices[4 * t + 1]);
  compute_neighbors(tri);
  report("Kuhn triangulation, topology", validate(tri, plc, ValidationLevel::Topology));
  report("Kuhn triangulation, full", validate(tri, plc));

  Triangulation<3> missing = tri;
  missing.simplices.resize(5 * 4);
  compute_neighbors(missing);
  report("one tetrahedron removed", validate(missing, plc));
  return 0;
}
