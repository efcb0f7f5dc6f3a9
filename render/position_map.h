// A position map (`baize sweep --png`, docs/positional.md): the table with the cue ball's finishing
// position for each grid point of a sweep, its colour from the first varied parameter (a colour
// scale, render/overlay_items.h), its size from the second, its shape from the outcome, and with
// execution error the 1-sigma ellipse of the noisy finishing positions around their mean.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/io/table.h"
#include "render/draw_items.h"

namespace baize::render {

enum class MapOutcome {
  ObjectPocketed,   // a disc
  CueBallPocketed,  // a square (drawn where it fell; counts before a pot: it is the foul)
  Missed,           // a triangle: neither
};

struct SpreadEllipse {
  Eigen::Vector2d mean_m = Eigen::Vector2d::Zero();
  double sd_major_m = 0, sd_minor_m = 0;
  double major_axis_rad = 0;  // from +x
};

struct MapPoint {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // the noise-free finishing position
  MapOutcome outcome = MapOutcome::Missed;
  double colour_fraction = 0;  // the first parameter's place in its range, [0, 1]
  double size_fraction = 0.5;  // the second's, [0, 1] (0.5 with one parameter)
  std::optional<SpreadEllipse> spread;
};

// A varied parameter's name and range, for the legend.
struct MapAxis {
  std::string name;
  double first = 0, last = 0;
};

// Marker sizes in pixels (times the pixel size): the second parameter's first value gets the
// smallest, its last the largest; with one parameter all get the middle.
constexpr double kMinMarker_px = 9;
constexpr double kMaxMarker_px = 21;
constexpr double kMarkerEdge_px = 1.5;
constexpr double kSpreadWidth_px = 2;  // the ellipses' line width

double markerSize_px(double size_fraction);

// axes: one or two (the second sets the size). Draws ellipses first, then the markers in order, so
// the last grid points lie on top.
Picture buildPositionMap(const engine::Table& table, const std::vector<MapPoint>& points,
                         const std::vector<MapAxis>& axes, double pixel_size_m, int noise_samples);

}  // namespace baize::render
