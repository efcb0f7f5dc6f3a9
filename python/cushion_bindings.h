// baize.cushion_impact: the Mathavan 2010 cushion model on one impact, with the parameters and
// defaults of `baize cushion` (speed, angle from the cushion line, spins in units of V0/R).
#pragma once

#include <pybind11/pybind11.h>

namespace baize::python {

// Registers baize.cushion_impact.
void bindCushion(pybind11::module_& module);

}  // namespace baize::python
