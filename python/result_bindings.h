// baize.Result: one simulated shot as Python sees it (its events, where the balls stopped, what it
// pocketed, its first ball hit and foul, and positions sampled from its exact trajectories).
#pragma once

#include <pybind11/pybind11.h>

#include "python/shot_run.h"

namespace baize::python {

// A new baize.Result owning the shot (pybind11's record of the class looked up once, not by the
// type's name on every call as its general cast does; a shot's cost is small enough for it to show).
pybind11::object resultObject(ShotRun&& shot);

// Registers baize.Event and baize.Result.
void bindResult(pybind11::module_& module);

}  // namespace baize::python
