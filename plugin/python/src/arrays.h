// numpy arrays in and out. Input arrays are checked here for what numpy can get wrong (shape,
// dtype); what the geometry can get wrong (NaN, ids out of range, open surfaces) is io's and
// core's to say, as for files.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sweepcdt::python {

namespace py = pybind11;

// An (n, columns) array of real numbers as float64, row-major; throws ValueError / TypeError naming
// `what` otherwise. columns = -1 accepts any width >= 1 (returned in *width).
std::vector<double> real_matrix(const py::handle& array, const char* what, int columns, int* width = nullptr);

// An (n, columns) integer array (any integer dtype; floats are refused: an id is not a measurement).
std::vector<int64_t> index_matrix(const py::handle& array, const char* what, int columns);

// A one-dimensional integer array of `length` entries.
std::vector<int64_t> index_vector(const py::handle& array, const char* what, std::size_t length);

// numpy arrays that own a copy of the data, shaped (size / columns, columns) (columns 0: 1-D).
template <class Out, class In>
py::array_t<Out> to_numpy(const std::vector<In>& data, std::size_t columns) {
  std::vector<py::ssize_t> shape;
  if (columns == 0) shape = {static_cast<py::ssize_t>(data.size())};
  else shape = {static_cast<py::ssize_t>(data.size() / columns), static_cast<py::ssize_t>(columns)};
  py::array_t<Out> out(shape);
  Out* p = out.mutable_data();
  for (std::size_t i = 0; i < data.size(); ++i) p[i] = static_cast<Out>(data[i]);
  return out;
}

}  // namespace sweepcdt::python
