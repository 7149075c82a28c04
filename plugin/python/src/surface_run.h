// A surface through the converter's pipeline, without the GIL (running.h):
//   Soup ──io::plc_of_soup──► Plc<3> ──cdt──► [check: validate_triangulated] ──io::volume_mesh_of──► VolumeMesh
// and the result as the dict sweepcdt.TetMesh is built from.
#pragma once
#include <pybind11/pybind11.h>

#include <vector>

#include "options.h"
#include "running.h"
#include "sweepcdt/io/snap.h"
#include "sweepcdt/io/soup.h"
#include "sweepcdt/io/volume_mesh.h"

namespace sweepcdt::python {

struct SurfaceRun {
  io::VolumeMesh mesh;
  std::vector<uint32_t> point_ids;  // per input point: its id in mesh.points, or kNone (unused)
  CdtStatistics cdt;
  io::SnapReport snap;
  uint64_t input_points = 0, input_triangles = 0;
  bool validated = false;
  double seconds_surface = 0, seconds_validate = 0, seconds_total = 0;
};

// Call with the GIL released. Throws what io and core throw, NotValid, CancelledError.
SurfaceRun run_surface(const io::Soup& soup, const RunKeywords& keywords, Watch& watch);

// With the GIL: numpy arrays and the stats dict.
py::dict result_dict(const SurfaceRun& run, const RunKeywords& keywords);

}  // namespace sweepcdt::python
