// Draws a shot with the installed Baize::render into a PNG, then checks the file with libpng
// itself rather than Baize's reader: it decodes, it has the size asked for, and something was
// drawn (more than one colour). Exit 0 when all hold.
// Usage: render_consumer OUT.png
#include <png.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <set>
#include <vector>

#include "engine/io/scene.h"
#include "render/camera.h"
#include "render/gl_renderer.h"
#include "render/osmesa_context.h"
#include "render/png_writer.h"
#include "render/shot_picture.h"
#include "render/shot_record.h"

namespace {

constexpr int kWidth_px = 320, kHeight_px = 160;  // the size asked for: 2:1, as the table

baize::engine::Scene scene() {
  using namespace baize::engine;
  Scene s;
  s.source = "render consumer";
  s.table = builtinTable("pool-9ft");
  s.ball_set = builtinBallSet("pool");
  s.cue_ball = "cue";
  s.balls = {{"cue", {-0.6, 0.05}}, {"1", {0.3, 0.0}}};
  s.shot.speed_mps = 2.0;
  s.shot.heading_rad = std::atan2(-0.05, 0.9);  // at the 1 ball
  return s;
}

void draw(const std::string& path) {
  namespace render = baize::render;
  const baize::engine::Scene shot = scene();
  const render::ShotRecord record = render::shotRecordOf(shot, baize::engine::runScene(shot, true));
  render::OsmesaContext context;
  render::GlRenderer renderer(context);
  render::PictureOptions options;
  options.pixel_size_m = render::pixelSizeFor(record.table, kWidth_px, kHeight_px);
  const render::Picture picture = render::buildShotPicture(record, options);
  renderer.draw(picture, render::cameraFor(picture, render::View::Top, kWidth_px, kHeight_px));
  render::writePng(renderer.readImage(), path);
}

// Whether the file is a PNG of the size asked for with something drawn in it; says what is wrong.
bool check(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    std::cerr << "FAIL: " << path << " is not a PNG libpng reads: " << image.message << "\n";
    return false;
  }
  if (image.width != kWidth_px || image.height != kHeight_px) {
    std::cerr << "FAIL: " << path << " is " << image.width << " x " << image.height << ", not "
              << kWidth_px << " x " << kHeight_px << "\n";
    png_image_free(&image);
    return false;
  }
  image.format = PNG_FORMAT_RGBA;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) {
    std::cerr << "FAIL: " << path << " does not decode: " << image.message << "\n";
    return false;
  }
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 3 < pixels.size(); i += 4)
    colours.insert(std::uint32_t{pixels[i]} << 24 | std::uint32_t{pixels[i + 1]} << 16 |
                   std::uint32_t{pixels[i + 2]} << 8 | pixels[i + 3]);
  if (colours.size() < 2) {
    std::cerr << "FAIL: " << path << " is one colour: nothing was drawn\n";
    return false;
  }
  std::cout << path << ": " << image.width << " x " << image.height << " PNG, " << colours.size()
            << " colours\n";
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: render_consumer OUT.png\n";
    return 2;
  }
  try {
    draw(argv[1]);
  } catch (const std::exception& e) {
    std::cerr << "FAIL: drawing " << argv[1] << ": " << e.what() << "\n";
    return 1;
  }
  return check(argv[1]) ? 0 : 1;
}
