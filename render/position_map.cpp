#include "render/position_map.h"

#include <algorithm>
#include <sstream>
#include <utility>
#include <variant>

#include "render/overlay_items.h"
#include "render/table_picture.h"

namespace baize::render {
namespace {

std::string rangeText(const MapAxis& axis) {
  std::ostringstream out;
  out << axis.name << " " << axis.first << " to " << axis.last;
  return out.str();
}

MarkerShape shapeOf(MapOutcome outcome) {
  switch (outcome) {
    case MapOutcome::ObjectPocketed:
      return MarkerShape::Disc;
    case MapOutcome::CueBallPocketed:
      return MarkerShape::Square;
    case MapOutcome::Missed:
      break;
  }
  return MarkerShape::Triangle;
}

}  // namespace

double markerSize_px(double size_fraction) {
  return kMinMarker_px + (kMaxMarker_px - kMinMarker_px) * std::clamp(size_fraction, 0.0, 1.0);
}

Picture buildPositionMap(const engine::Table& table, const std::vector<MapPoint>& points,
                         const std::vector<MapAxis>& axes, double pixel_size_m, int noise_samples) {
  Picture picture;
  addTable(table, picture);
  for (const MapPoint& p : points) {
    if (!p.spread) continue;
    Stroke ellipse = ellipseOutline(p.spread->mean_m, p.spread->sd_major_m, p.spread->sd_minor_m,
                                    p.spread->major_axis_rad, kSpreadWidth_px * pixel_size_m,
                                    scaleColour(p.colour_fraction));
    picture.items.emplace_back(std::in_place_type<Stroke>, std::move(ellipse));
  }
  for (const MapPoint& p : points) {
    addMarker(picture, shapeOf(p.outcome), p.position_m,
              markerSize_px(p.size_fraction) * pixel_size_m, kMarkerEdge_px * pixel_size_m,
              scaleColour(p.colour_fraction));
  }
  if (!axes.empty()) {
    picture.legend.push_back({true, scaleColour(0), false, "colour: " + rangeText(axes[0])});
    picture.legend.push_back(
        {true, scaleColour(1), false, "(dark blue, purple, pink, orange, yellow)"});
  }
  if (axes.size() > 1) {
    picture.legend.push_back(
        {false, {}, false, "size: " + rangeText(axes[1]) + " (small to large)"});
  }
  picture.legend.push_back({false,
                            {},
                            false,
                            "disc: object ball pocketed, square: cue ball pocketed, "
                            "triangle: neither"});
  if (noise_samples > 0) {
    picture.legend.push_back({false,
                              {},
                              false,
                              "rings: 1-sigma ellipse of " + std::to_string(noise_samples) +
                                  " noisy samples' finishing positions"});
  }
  return picture;
}

}  // namespace baize::render
