#include "check_files.h"

#include <pybind11/stl.h>

#include "options.h"
#include "sweepcdt/io/verify_mesh.h"

namespace sweepcdt::python {

py::dict check_files(const std::filesystem::path& input, const std::filesystem::path& output, const std::optional<std::string>& facets,
                     std::optional<double> snap) {
  const RunKeywords k = run_keywords(std::nullopt, std::nullopt, facets, snap, false);
  MeshVerification v;
  {
    py::gil_scoped_release release;
    v = io::verify_mesh_files(input, output, k.facets, k.snap);
  }
  py::dict r;
  r["valid"] = v.ok();
  r["problems"] = v.problems;
  r["total_problems"] = v.total_problems;
  r["facets"] = name_of(k.facets);
  r["steiner_points"] = v.steiner_points;
  r["steiner_exactly_on"] = v.steiner_exactly_on;
  r["input_facets"] = v.facets;
  r["boundary_triangles"] = v.boundary_triangles;
  r["file_boundary"] = v.file_boundary;
  r["file_tags"] = v.file_tags;
  r["validated"] = v.validated;
  r["perturbation_order"] = v.perturbation_order;
  r["suggest_coplanar"] = v.suggest_coplanar;
  r["suggest_triangles"] = v.suggest_triangles;
  return r;
}

}  // namespace sweepcdt::python
