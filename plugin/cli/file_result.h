// What happened to one input: the outcome, the counts and the times that the summary line and
// --stats report.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "exit_codes.h"
#include "sweepcdt/cdt.h"
#include "sweepcdt/io/snap.h"

namespace sweepcdt::cli {

struct OutputFile {
  std::string file;    // the name asked for (TetGen: e.g. the .node file; .ele and .face beside it)
  std::string format;  // format word ("mesh", "vtu", ..., "node", "simplices")
};

struct FileResult {
  std::string input;
  std::vector<OutputFile> outputs;  // as requested: all written (code kOk) or none
  int code = kOk;             // exit code of this file
  std::string message;        // the failure's one line (empty on success)
  std::vector<std::string> details;   // failure: the first problems; success: hints
  std::vector<std::string> warnings;  // the file converted, but the user should know (one line each)

  int dimension = 3;
  uint64_t input_points = 0, input_simplices = 0;  // after welding (and --snap); triangles for surfaces
  io::SnapReport snap;                             // --snap: what moved
  uint64_t simplices = 0;                          // tetrahedra in 3D
  uint64_t boundary_triangles = 0, regions = 0;    // volume meshes only
  bool computed = false;                           // cdt() returned (statistics are meaningful)
  CdtStatistics cdt;
  bool validated = false;                          // --check ran and passed
  double seconds_read = 0, seconds_validate = 0, seconds_write = 0, seconds_total = 0;
};

}  // namespace sweepcdt::cli
