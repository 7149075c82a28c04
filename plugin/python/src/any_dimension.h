// sweepcdt.cdt(): the CDT of a PLC of any dimension D = 2..5 given as arrays (points n x D,
// constraining simplices m x D, optional exterior notations and tags). `facets` matters in D = 3 only.
#pragma once
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

namespace sweepcdt::python {

namespace py = pybind11;

py::dict cdt_any_dimension(const py::handle& points, const py::handle& simplices, const py::handle& exterior,
                           const py::handle& tags, const std::optional<std::string>& algorithm,
                           const std::optional<std::string>& steiner,
                           const std::optional<std::string>& facets, bool check, py::object progress);

}  // namespace sweepcdt::python
