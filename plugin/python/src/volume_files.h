// Volume-mesh files from Python: io::read_volume_mesh / io::write_volume_mesh on numpy arrays
// (for the FreeCAD workbench's import/export, and anyone converting meshes).
#pragma once
#include <pybind11/pybind11.h>

#include <filesystem>
#include <optional>
#include <string>

namespace sweepcdt::python {

namespace py = pybind11;

// The dict sweepcdt.TetMesh is built from (no statistics beyond the counts).
py::dict read_volume_mesh(const std::filesystem::path& file);

// Tetrahedra in file order (det[b-a, c-a, d-a] > 0, as TetMesh holds them); regions, boundary
// triangles and their ids optional. Throws ValueError for bad arrays, OutputFailure if unwritable.
void write_volume_mesh(const std::filesystem::path& file, const py::handle& points, const py::handle& tetrahedra,
                       const py::handle& regions, const py::handle& triangles, const py::handle& triangle_ids,
                       const std::optional<std::string>& format);

}  // namespace sweepcdt::python
