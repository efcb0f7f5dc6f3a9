// Pictures with overlays for the positional commands (`baize sweep --png`, `baize check --png`,
// `baize plan --png`): one off-screen renderer for many PNGs, and a cue-ball region (a suite's
// expectation or a plan's goal) drawn over a shot.
#pragma once

#include <memory>
#include <string>

#include "engine/io/scene.h"
#include "engine/play/shot_outcome.h"
#include "engine/play/shot_suite.h"
#include "render/draw_items.h"

namespace baize::tools {

// The size of the overlay pictures, px (the size `baize render` uses by default).
constexpr int kOverlayWidth_px = 1600;
constexpr int kOverlayHeight_px = 800;
// Region outlines and paths, px wide: thicker than a trace so they stand out.
constexpr double kRegionLine_px = 3;

// The region's outline colour: magenta, a colour no ball, cloth or trace uses.
render::Rgba regionColour();

// Draws `region` on `picture`: a circle or rectangle outline; for a straight shot the ghost-ball
// position (a ring of the ball's radius) and the two paths, cue ball to ghost ball and object ball
// to the pocket's mouth centre, from the balls' final positions in `outcome`.
void addRegion(render::Picture& picture, const engine::Scene& scene,
               const engine::ShotOutcome& outcome, const engine::CueBallRegion& region,
               double pixel_size_m);

// A picture of the scene's shot as `baize render` draws it (top view).
render::Picture shotPicture(const engine::Scene& scene, const engine::SceneRun& run,
                            double pixel_size_m);

// An off-screen renderer that writes pictures as PNG (each file whole or not at all).
class PngPainter {
 public:
  PngPainter();
  ~PngPainter();
  void write(const render::Picture& picture, const std::string& path);

 private:
  struct Gl;
  std::unique_ptr<Gl> gl_;
};

}  // namespace baize::tools
