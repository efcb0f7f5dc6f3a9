#include "python/render_bindings.h"

#include <pybind11/stl.h>

#include <optional>

#include "python/result_bindings.h"
#include "render/camera.h"
#include "render/gl_renderer.h"
#include "render/osmesa_context.h"
#include "render/png_writer.h"
#include "render/shot_picture.h"
#include "render/shot_record.h"

namespace baize::python {
namespace {

namespace py = pybind11;

void checkSide(const char* name, int pixels) {
  if (pixels < render::kMinImageSide_px || pixels > render::kMaxImageSide_px) {
    throw py::value_error(std::string(name) + " = " + std::to_string(pixels) +
                          " is not allowed: it must lie in [" +
                          std::to_string(render::kMinImageSide_px) + ", " +
                          std::to_string(render::kMaxImageSide_px) + "] px");
  }
}

void renderPng(const engine::Scene& scene, const std::string& path,
               std::optional<ShotRun*> result, int width, int height, const std::string& view,
               bool legend) {
  checkSide("width", width);
  checkSide("height", height);
  if (view != "top" && view != "angled")
    throw py::value_error("view = '" + view + "' is not allowed: it must be 'top' or 'angled'");
  if (path.empty()) throw py::value_error("path is empty: name the PNG file to write");
  // The result's trajectories, recorded now if they were not yet: under the GIL, as it changes
  // the result.
  const engine::SceneRun* recorded = result ? &recordedRunOf(**result) : nullptr;
  const py::gil_scoped_release released;
  const engine::SceneRun run = recorded ? *recorded : engine::runScene(scene, true);
  const render::ShotRecord record = render::shotRecordOf(scene, run);
  render::OsmesaContext context;
  render::GlRenderer renderer(context);
  render::PictureOptions options;
  options.pixel_size_m = render::pixelSizeFor(record.table, width, height);
  options.legend = legend;
  options.time_s = record.end_time_s;
  const render::Picture picture = render::buildShotPicture(record, options);
  renderer.draw(picture, render::cameraFor(picture, render::viewNamed(view), width, height));
  render::writePng(renderer.readImage(), path);
}

}  // namespace

void bindRender(py::module_& module) {
  module.def("render_png", &renderPng, py::arg("scene"), py::arg("path"), py::kw_only(),
             py::arg("result") = py::none(), py::arg("width") = 1600, py::arg("height") = 800,
             py::arg("view") = "top", py::arg("legend") = false,
             "Draws the shot (its result when given, else simulated now) to a PNG file, as "
             "`baize simulate --png`: the traces, solid while rolling and dashed while sliding, "
             "and the balls where they stopped. view: 'top' or 'angled'.");
}

}  // namespace baize::python
