// The module baize._baize: the engine as the Python package baize sees it (docs/python.md). Each
// part registers itself from its own file; python/baize/__init__.py re-exports them.
#include <pybind11/pybind11.h>

#include "python/cushion_bindings.h"
#include "python/result_bindings.h"
#include "python/scene_bindings.h"
#include "python/shot_batch.h"
#include "python/simulate_function.h"
#ifdef BAIZE_WITH_RENDER
#include "python/render_bindings.h"
#endif

PYBIND11_MODULE(_baize, module) {
  module.doc() = "Baize's engine: scenes, shots, results, the cushion model.";
  baize::python::bindScene(module);
  baize::python::bindResult(module);
  baize::python::bindSimulate(module);
  baize::python::bindShotBatch(module);
  baize::python::bindCushion(module);
#ifdef BAIZE_WITH_RENDER
  baize::python::bindRender(module);
  module.attr("with_render") = true;
#else
  module.attr("with_render") = false;
#endif
}
