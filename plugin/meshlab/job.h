// What the MeshLab filter asks of sweepcdt, and what it gets back — the bridge between the MeshLab
// side of the plugin (C++14-era MeshLab and vcglib headers, compiled as C++17) and the library (C++20).
// This header includes neither: plain vectors and strings only.
//
//   layer (float vertices, faces) ──run_job()──► volume file written + cut-away layer, or an error
//                                                 naming the faces to select
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace sweepcdt::meshlab {

// The choices of the filter's enum parameters, in order, and the library's defaults among them.
struct Choices {
  std::vector<std::string> algorithms;   // kAlgorithms' names: "cavity-sweep" (the default), "sweep-sphere", ...
  std::vector<std::string> steiner;      // "auto", "none"
  std::vector<std::string> facets;       // "triangles", "coplanar"
  std::vector<std::string> axes;         // "x", "y", "z"
  std::vector<std::string> colourings;   // "element quality", "region"
  int default_algorithm, default_steiner, default_facets;
};
Choices choices();

struct JobInput {
  std::string name;                 // the layer's name, for messages
  std::vector<double> points;       // n x 3: the layer's float coordinates, widened exactly
  std::vector<uint32_t> triangles;  // m x 3 point ids: the layer's faces, in order
  std::string output;               // the volume file; its extension picks the format
  int algorithm = 0, steiner = 0, facets = 0;  // indices into Choices
  std::string snap = "0";           // relative snap tolerance (sweepcdt --snap), 0 = none
  bool verify = false;              // validate() the result once more before writing
  int cut_axis = 0;                 // 0, 1, 2 = x, y, z
  double cut_fraction = 0.5;        // where the plane cuts, in [0, 1] of the mesh's extent
  std::function<void(int percent, const char* phase)> progress;  // may be empty
};

struct JobResult {
  bool ok = false;
  std::string error;                 // one line, when !ok
  std::vector<std::string> details;  // further lines: the problems found, first ones first
  std::vector<uint32_t> select;      // when !ok: input triangles to select (sorted, distinct)
  std::vector<std::string> log;      // what was done, one line each

  // The cut-away layer (when ok): triangles over points, with a value per triangle.
  std::vector<double> points;        // k x 3
  std::vector<uint32_t> triangles;   // l x 3, counterclockwise seen from outside the kept tetrahedra
  std::vector<double> quality;       // l: radius ratio (0..1) of the tetrahedron behind the triangle
  std::vector<int32_t> region;       // l: its region (0-based)
  std::vector<uint8_t> on_cut;       // l: 1 for a facet exposed by the cut, 0 for the domain boundary
};

// Never throws: every failure is in the result.
JobResult run_job(const JobInput& input);

}  // namespace sweepcdt::meshlab
