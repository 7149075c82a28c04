// A PLC of any dimension D = 2..5 from numpy arrays (points n x D, constraining simplices m x D,
// optional exterior notations -1/0/1 and tags), shared by sweepcdt.cdt and sweepcdt.EditableCdt.
#pragma once
#include <pybind11/pybind11.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "sweepcdt/plc.h"

namespace sweepcdt::python {

namespace py = pybind11;

// The arrays as read and shape-checked, before the dimension is known at compile time.
struct PlcArrays {
  int dimension = 0;
  std::vector<double> points;
  std::vector<int64_t> simplices, exterior, tags;  // exterior, tags: empty when not given
  const char* simplices_name = "simplices";        // how messages name the constraints
};

// Throws ValueError/TypeError naming the array; dimension must be 2..5.
PlcArrays plc_arrays(const py::handle& points, const py::handle& simplices, const py::handle& exterior,
                     const py::handle& tags, const char* simplices_name = "simplices");

// Out-of-range point ids are core's to report (PlcError names the simplex); only what does not fit
// uint32 is refused here (ValueError), so that it is not wrapped into a valid id.
template <int D>
Plc<D> plc_of(PlcArrays a);

// core's orient (Shewchuk's) is sign det[p_0 - p_D; ...; p_{D-1} - p_D], which is (-1)^D times the
// usual det[p_1 - p_0; ...; p_D - p_0]: for odd D, swapping the last two vertices turns a simplex
// positive in one sense into one positive in the other (its own inverse).
template <int D>
void swap_orientation_convention(std::vector<uint32_t>& simplices) {
  if constexpr (D % 2 == 1)
    for (std::size_t t = 0; t + D < simplices.size(); t += D + 1) std::swap(simplices[t + D - 1], simplices[t + D]);
}

// Exterior notations as the Python API spells them (-1, 0, 1).
int64_t exterior_code(ExteriorSide side);

}  // namespace sweepcdt::python
