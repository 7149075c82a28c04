// Sample: the main job of sweepcdt on one file — import a closed surface, tetrahedralize its
// interior (SweepCDT, sweep sphere; Steiner points where the surface has no CDT as given), check the
// result with validate(), and report.
//
//   build/samples/tetrahedralize samples/data/knot1.drc
#include <chrono>
#include <cstdio>

#include "sweepcdt/cdt.h"
#include "sweepcdt/io/to_plc.h"
#include "sweepcdt/validate.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SURFACE (OFF, STL, OBJ, PLY, glTF/GLB, Draco .drc)\n", argv[0]);
    return 2;
  }
  using namespace sweepcdt;
  try {
    const auto start = std::chrono::steady_clock::now();
    const Plc<3> plc = io::import_plc(argv[1]);
    Options options;
    options.steiner = SteinerMode::Auto;
    CdtStatistics stats;
    options.statistics = &stats;
    Plc<3> triangulated;
    const Triangulation<3> tri = cdt(plc, options, &triangulated);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu triangles, %zu vertices\n", argv[1], plc.num_simplices(), plc.num_points());
    std::printf("CDT (%s): %zu tetrahedra, %zu Steiner points, %.2f s\n", to_string(stats.algorithm),
                tri.num_simplices(), tri.steiner_on.size(), seconds);
    const ValidationReport report = validate_triangulated(tri, triangulated);
    std::printf("validate(): %s\n", report.ok() ? "constrained Delaunay, constraints present, domain covered" : report.summary().c_str());
    return report.ok() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[1], e.what());
    return 3;
  }
}
