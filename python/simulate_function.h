// baize.simulate, one shot, and the C++ reference its cost is measured against.
#pragma once

#include <pybind11/pybind11.h>

namespace baize::python {

// Registers baize.simulate and, for tools/bench_python.py, _baize._native_run_times_ns and
// _baize._native_clock_ns.
void bindSimulate(pybind11::module_& module);

}  // namespace baize::python
