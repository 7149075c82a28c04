// sweepcdt.EditableCdt's compiled half: EditableCdt<D> (sweepcdt/editable_cdt.h, paper §5) for
// D = 2..5 behind one Python class, _sweepcdt.EditableCdt. Its docstrings are in sweepcdt/editable.py.
#pragma once
#include <pybind11/pybind11.h>

namespace sweepcdt::python {

void register_editable(pybind11::module_& m);

}  // namespace sweepcdt::python
