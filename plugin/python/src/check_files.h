// sweepcdt.check_files from Python: io::verify_mesh_files (sweepcdt/io/verify_mesh.h), the proof
// `sweepcdt check` runs, with its report as a dict.
#pragma once
#include <pybind11/pybind11.h>

#include <filesystem>
#include <optional>
#include <string>

namespace sweepcdt::python {

namespace py = pybind11;

// `facets`/`snap` as the converter spells them (nullopt: its defaults). Returns {"valid", "problems"
// (the first ones), "total_problems", "steiner_points", ...}; throws as the readers do (unreadable files).
py::dict check_files(const std::filesystem::path& input, const std::filesystem::path& output, const std::optional<std::string>& facets,
                     std::optional<double> snap);

}  // namespace sweepcdt::python
