// baize.render_png: a shot drawn off-screen to a PNG file, as `baize simulate --png` draws it.
// Only in a build with rendering (BAIZE_WITH_RENDER).
#pragma once

#include <pybind11/pybind11.h>

namespace baize::python {

// Registers baize.render_png.
void bindRender(pybind11::module_& module);

}  // namespace baize::python
