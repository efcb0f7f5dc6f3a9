// baize.simulate and baize.simulate_many: shots run with the GIL released, many of them on threads
// of their own, results in the input's order and the same to the bit as one by one.
#pragma once

#include <pybind11/pybind11.h>

namespace baize::python {

// Registers baize.simulate, baize.simulate_many, baize.ShotError and baize.BatchError.
void bindShotBatch(pybind11::module_& module);

}  // namespace baize::python
