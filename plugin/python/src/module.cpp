// sweepcdt._sweepcdt: the compiled half of the Python module. The public API, with its docstrings,
// is sweepcdt/__init__.py; these functions take what it passes on and return plain dicts of numpy
// arrays. Every C++ exception becomes a Python exception (errors.h).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <filesystem>

#include "any_dimension.h"
#include "arrays.h"
#include "check_files.h"
#include "editable.h"
#include "errors.h"
#include "options.h"
#include "running.h"
#include "surface_run.h"
#include "volume_files.h"
#include "sweepcdt/io/error.h"
#include "sweepcdt/io/read.h"
#include "sweepcdt/io/surface_arrays.h"
#include "sweepcdt/io/volume_mesh.h"

namespace py = pybind11;
using namespace sweepcdt;
using namespace sweepcdt::python;

namespace {

using Opt = std::optional<std::string>;

py::dict tetrahedralize(const py::handle& points, const py::handle& triangles, const Opt& algorithm, const Opt& steiner,
                        const Opt& facets, std::optional<double> snap, bool check, py::object progress,
                        const std::string& name) {
  const RunKeywords k = run_keywords(algorithm, steiner, facets, snap, check);
  const std::vector<double> p = real_matrix(points, "points", 3);
  const std::vector<int64_t> t = index_matrix(triangles, "triangles", 3);
  Watch watch(std::move(progress));
  SurfaceRun run;
  try {
    py::gil_scoped_release release;
    run = run_surface(io::soup_of_arrays(p, t, name), k, watch);
  } catch (const CancelledError&) {
    watch.rethrow();
  }
  return result_dict(run, k);
}

py::dict read_surface(const std::filesystem::path& file) {
  io::Soup soup;
  {
    py::gil_scoped_release release;
    soup = io::read_soup(file);
  }
  py::dict r;
  r["points"] = to_numpy<double>(soup.points, 3);
  r["triangles"] = to_numpy<int64_t>(soup.triangles, 3);
  r["format"] = io::to_string(soup.format);
  return r;
}

// The format of each output: `format` (one word for all) or each file's extension, decided before
// any work, as the converter does.
std::vector<io::MeshFormat> output_formats(const std::vector<std::filesystem::path>& outputs, const Opt& format) {
  if (outputs.empty()) throw py::value_error("mesh_file needs at least one output file");
  std::vector<io::MeshFormat> formats;
  for (const auto& out : outputs) {
    std::optional<io::MeshFormat> f = format ? io::mesh_format_named(*format) : io::mesh_format_of(out);
    if (!f) {
      if (format) throw py::value_error("unknown format '" + *format + "' (mesh, vtu, msh, msh22, node, inp)");
      throw py::value_error(out.string() + ": unknown extension; use .mesh, .vtu, .msh, .node/.ele/.face or .inp, or format=");
    }
    formats.push_back(*f);
  }
  return formats;
}

py::dict mesh_file(const std::filesystem::path& input, const std::vector<std::filesystem::path>& outputs,
                   const Opt& format, const Opt& algorithm, const Opt& steiner, const Opt& facets,
                   std::optional<double> snap, bool check, py::object progress) {
  const RunKeywords k = run_keywords(algorithm, steiner, facets, snap, check);
  const std::vector<io::MeshFormat> formats = output_formats(outputs, format);
  Watch watch(std::move(progress));
  SurfaceRun run;
  try {
    py::gil_scoped_release release;
    watch.phase("reading");
    run = run_surface(io::read_soup(input), k, watch);
    // Last chance to stop: once writing starts, it completes (each file is atomic).
    watch.phase("writing");
    std::size_t written = 0;
    try {
      for (; written < outputs.size(); ++written) io::write_volume_mesh(outputs[written], run.mesh, formats[written]);
    } catch (const std::exception& e) {
      // A conversion is complete or leaves nothing: remove the outputs already written.
      std::error_code ec;
      for (std::size_t j = 0; j < written; ++j)
        for (const auto& f : io::volume_mesh_files(outputs[j], formats[j])) std::filesystem::remove(f, ec);
      if (dynamic_cast<const std::bad_alloc*>(&e)) throw;
      throw OutputFailure(e.what());
    }
  } catch (const CancelledError&) {
    watch.rethrow();
  }
  return result_dict(run, k);
}

py::dict defaults() {
  const RunKeywords k = converter_defaults();
  py::dict d;
  d["algorithm"] = to_string(k.algorithm);
  d["steiner"] = name_of(k.steiner);
  d["facets"] = name_of(k.facets);
  return d;
}

py::list algorithms() {
  py::list names;
  for (const Algorithm a : kAlgorithms) names.append(to_string(a));
  return names;
}

}  // namespace

PYBIND11_MODULE(_sweepcdt, m) {
  m.doc() = "sweepcdt's compiled core; use the functions of the sweepcdt package.";
  register_error_translator();
  m.def("tetrahedralize", &tetrahedralize, py::arg("points"), py::arg("triangles"), py::arg("algorithm"),
        py::arg("steiner"), py::arg("facets"), py::arg("snap"), py::arg("check"), py::arg("progress"), py::arg("name"));
  m.def("read_surface", &read_surface, py::arg("path"));
  m.def("mesh_file", &mesh_file, py::arg("input"), py::arg("outputs"), py::arg("format"), py::arg("algorithm"),
        py::arg("steiner"), py::arg("facets"), py::arg("snap"), py::arg("check"), py::arg("progress"));
  m.def("cdt", &cdt_any_dimension, py::arg("points"), py::arg("simplices"), py::arg("exterior"), py::arg("tags"),
        py::arg("algorithm"), py::arg("steiner"), py::arg("facets"), py::arg("check"), py::arg("progress"));
  register_editable(m);
  m.def("read_volume_mesh", &read_volume_mesh, py::arg("path"));
  m.def("write_volume_mesh", &write_volume_mesh, py::arg("path"), py::arg("points"), py::arg("tetrahedra"),
        py::arg("regions"), py::arg("triangles"), py::arg("triangle_ids"), py::arg("format"));
  m.def("check_files", &check_files, py::arg("input"), py::arg("output"), py::arg("facets"), py::arg("snap"));
  m.def("defaults", &defaults, "The converter's defaults: {'algorithm': ..., 'steiner': ..., 'facets': ...}");
  m.def("algorithms", &algorithms, "The algorithms' names, the default first.");
}
