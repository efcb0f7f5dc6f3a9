#include "tools/baize/picture_commands.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "engine/io/table.h"
#include "render/camera.h"
#include "render/gl_renderer.h"
#include "render/osmesa_context.h"
#include "render/png_writer.h"
#include "render/shot_picture.h"
#include "render/shot_record.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/progress.h"

namespace baize::tools {
namespace {

struct BenchRenderFlags {
  int width_px = 1600;
  int height_px = 800;
  std::string view = "top";
  int repeat = 21;  // timed renders; the median is reported
};

constexpr int kMaxRepeat = 10000;

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

void runBenchRender(const BenchRenderFlags& flags) {
  render::validateImageSize(flags.width_px, flags.height_px);
  const render::View view = render::viewNamed(flags.view);
  if (flags.repeat < 1 || flags.repeat > kMaxRepeat) {
    rejectFlag("--repeat", flags.repeat, "it must lie in [1, 10000]");
  }
  const std::string scene = engine::assetsDirectory() + "/scenes/9-ball-break.json";
  const render::ShotRecord shot = render::loadShotRecord(scene);

  auto start = std::chrono::steady_clock::now();
  render::OsmesaContext context;
  render::GlRenderer renderer(context);
  const double setup_ms = millisecondsSince(start);

  const std::filesystem::path png =
      std::filesystem::temp_directory_path() / "baize-bench-render.png";
  render::PictureOptions options;
  options.pixel_size_m = render::pixelSizeFor(shot.table, flags.width_px, flags.height_px);
  std::vector<double> picture_ms, draw_ms, png_ms, total_ms;
  Progress progress("renders", flags.repeat);
  for (int i = 0; i < flags.repeat; ++i, progress.advance()) {
    start = std::chrono::steady_clock::now();
    const render::Picture picture = render::buildShotPicture(shot, options);
    const double built = millisecondsSince(start);
    renderer.draw(picture, render::cameraFor(picture, view, flags.width_px, flags.height_px));
    const render::Image image = renderer.readImage();
    const double drawn = millisecondsSince(start);
    render::writePng(image, png.string());
    const double written = millisecondsSince(start);
    picture_ms.push_back(built);
    draw_ms.push_back(drawn - built);
    png_ms.push_back(written - drawn);
    total_ms.push_back(written);
  }
  std::filesystem::remove(png);
  std::cout << std::fixed << std::setprecision(1);
  std::cout << "9-ball break, " << flags.width_px << " x " << flags.height_px << " px, "
            << flags.view << " view, " << renderer.samples() << " samples per pixel, "
            << renderer.glVersion() << "\n";
  std::cout << "context and shaders (once): " << setup_ms << " ms\n";
  std::cout << "median of " << flags.repeat << " renders: " << median(total_ms)
            << " ms (draw items " << median(picture_ms) << " ms, GL draw and read back "
            << median(draw_ms) << " ms, PNG " << median(png_ms) << " ms)\n";
}

}  // namespace

void addBenchRenderCommand(CLI::App& parent) {
  auto flags = std::make_shared<BenchRenderFlags>();
  CLI::App* command = parent.add_subcommand(
      "render", "Time drawing the 9-ball break to a PNG off-screen (median of repeated renders)");
  command->add_option("--width", flags->width_px, "picture width, px (default 1600)");
  command->add_option("--height", flags->height_px, "picture height, px (default 800)");
  command->add_option("--view", flags->view, "top (default) or angled");
  command->add_option("--repeat", flags->repeat, "timed renders (default 21)");
  command->callback([flags] {
    if (const int status = runReportingErrors("bench render", [&] { runBenchRender(*flags); })) {
      throw CLI::RuntimeError(status);
    }
  });
}

}  // namespace baize::tools
