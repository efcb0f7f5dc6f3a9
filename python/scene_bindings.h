// baize.Scene, baize.load_scene and baize.random_shots: scenes read by the engine's scene reader,
// from a file or from plain Python values (the document a file would hold), so that both are
// checked alike and refused with the same messages.
#pragma once

#include <pybind11/pybind11.h>

namespace baize::python {

// Registers baize.Scene, baize.load_scene and baize.random_shots.
void bindScene(pybind11::module_& module);

}  // namespace baize::python
