#pragma once
// `hmfnet.spectrum`, `hmfnet.theory` and `hmfnet.simulate` (as `_spectrum`, ... taking the CLI's
// tokens; hmfnet/__init__.py gives them keyword arguments).
#include <pybind11/pybind11.h>

namespace hmfnet::python {

void bind_commands(pybind11::module_& m);

}  // namespace hmfnet::python
