// baize.Scene, baize.load_scene and baize.random_shots: scenes read by the engine's scene reader,
// from a file or from plain Python values (the document a file would hold), so that both are
// checked alike and refused with the same messages.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "engine/io/scene.h"

namespace baize::python {

// The scene a Python argument holds, shared with it. Throws TypeError naming the argument as
// `name` ("scene", "scenes[3]") and what it is when it is not a baize.Scene (or is one not made).
std::shared_ptr<const engine::Scene> sceneArgument(pybind11::handle argument, const std::string& name);

// Registers baize.Scene, baize.load_scene and baize.random_shots.
void bindScene(pybind11::module_& module);

}  // namespace baize::python
