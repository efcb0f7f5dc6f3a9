// A shot as draw items (render/draw_items.h): the table (render/table_picture.h), then per ball its
// trace from the exact trajectory (solid while rolling, dashed while sliding), markers at the
// ball-ball, cushion and pocket events, a ring where each moved ball started, and the balls where
// they stand at the chosen time.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "render/draw_items.h"
#include "render/shot_record.h"

namespace baize::render {

struct PictureOptions {
  // Balls are drawn where they are at this time, s; traces and markers run up to it. Infinity (the
  // default) means the end of the shot.
  double time_s = std::numeric_limits<double>::infinity();
  bool traces = true;   // traces, event markers and start rings
  bool legend = false;  // a legend: each ball that moves, its speed and spin, and the key
  // About the size of one pixel on the cloth, m: sets line widths, marker sizes and how finely the
  // traces are sampled. pixelSizeFor() gives it for an image.
  double pixel_size_m = 0.002;
};

// The pixel size for a top view of `table` filling an image of this size.
double pixelSizeFor(const engine::Table& table, int width_px, int height_px);

// Trace and marker sizes in pixels (times PictureOptions::pixel_size_m).
constexpr double kTraceWidth_px = 3.0;
constexpr double kStripeCoreWidth_px = 1.0;  // the white centre line marking a striped ball's trace
constexpr double kTraceStep_px = 1.5;        // the longest straight piece of a sampled trace
constexpr double kDashOn_px = 9.0;           // sliding: dashes and gaps along the trace
constexpr double kDashOff_px = 6.0;
constexpr double kBallBallMarkerRadius_px = 6.0;
constexpr double kCushionMarkerRadius_px = 4.0;
constexpr double kPocketMarkerRadius_px = 8.0;
// Balls first set in motion slower than this get no legend row of their own but one shared line
// ("N more balls nudged"), m/s: in a frozen rack most balls only shiver, and rows for them would
// hide the table.
constexpr double kLegendMinSpeed_mps = 0.05;
// A ball that moved less than this from its start gets no start ring, m (well under a pixel).
constexpr double kMovedDistance_m = 1e-4;

// Marker colours: a ball-ball contact (dark ring at the contact point), a cushion or jaw hit
// (orange dot at the ball's centre), a ball falling into a pocket (red ring).
Rgba ballBallMarkerColour();
Rgba cushionMarkerColour();
Rgba pocketMarkerColour();

// The colour a ball of the set is drawn in (its main colour; white for the cue ball).
Rgba ballColour(const engine::BallSet& set, const std::string& id);

// The legend's line for a ball: its id, then the speed and spin it had when it was first set in
// motion (for the cue ball, as struck): "cue: 7.84 m/s, roll -12 rad/s, side 0 rad/s", where roll
// is the spin about the horizontal axis across the motion (+: topspin) and side the spin about the
// vertical (+: counterclockwise seen from above). Nothing for a ball that never moves.
std::optional<std::string> legendText(const std::string& id, const engine::Trajectory& trajectory);
// The speed a ball had when it was first set in motion, m/s (0 for a ball that never moves).
double firstSpeed(const engine::Trajectory& trajectory);

Picture buildShotPicture(const ShotRecord& shot, const PictureOptions& options);

}  // namespace baize::render
