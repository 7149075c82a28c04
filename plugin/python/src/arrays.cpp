#include "arrays.h"

#include <stdexcept>

namespace sweepcdt::python {
namespace {

// Anything array-like (lists, tuples, arrays of any layout) as a numpy array.
py::array as_array(const py::handle& object, const char* what) {
  if (object.is_none()) throw py::type_error(std::string(what) + " must be an array, not None");
  return py::array::ensure(object);
}

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

void check_shape(const py::array& a, const char* what, int columns) {
  const bool ok = a.ndim() == 2 && (columns < 0 ? a.shape(1) >= 1 : a.shape(1) == columns);
  if (!ok) {
    const std::string want = columns < 0 ? "(n, d)" : "(n, " + std::to_string(columns) + ")";
    throw py::value_error(std::string(what) + " must have shape " + want + ", not " + shape_text(a));
  }
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

}  // namespace

std::vector<double> real_matrix(const py::handle& object, const char* what, int columns, int* width) {
  py::array a = as_array(object, what);
  if (!a) throw py::type_error(std::string(what) + " must be array-like");
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error(std::string(what) + " must hold real numbers, not dtype " + dtype_text(a));
  check_shape(a, what, columns);
  if (width) *width = static_cast<int>(a.shape(1));
  auto c = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  return {c.data(), c.data() + c.size()};
}

std::vector<int64_t> index_matrix(const py::handle& object, const char* what, int columns) {
  py::array a = as_array(object, what);
  // An empty Python list arrives as float64; an empty array is still a valid (0, columns) shape.
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u' && !(a.size() == 0 && kind == 'f'))
    throw py::value_error(std::string(what) + " must be an integer array (point ids), not dtype " + dtype_text(a));
  check_shape(a, what, columns);
  if (kind == 'u' && a.itemsize() == 8) {
    // uint64 ids above 2^63 would wrap to negative int64: refuse them by name instead.
    auto u = py::array_t<uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for (py::ssize_t i = 0; i < u.size(); ++i)
      if (u.data()[i] > static_cast<uint64_t>(INT64_MAX))
        throw py::value_error(std::string(what) + ": id " + std::to_string(u.data()[i]) + " is out of range");
  }
  auto c = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  return {c.data(), c.data() + c.size()};
}

std::vector<int64_t> index_vector(const py::handle& object, const char* what, std::size_t length) {
  py::array a = as_array(object, what);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u' && !(a.size() == 0 && kind == 'f'))
    throw py::value_error(std::string(what) + " must be an integer array, not dtype " + dtype_text(a));
  if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != length)
    throw py::value_error(std::string(what) + " must have shape (" + std::to_string(length) + ",), not " + shape_text(a));
  auto c = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  return {c.data(), c.data() + c.size()};
}

}  // namespace sweepcdt::python
