// The benchmark charts' series: points with a setting as their label, grouped by solver or engine
// in the table's order, each series joined in order of x so that its line reads as a trade-off.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "render/line_chart.h"

namespace baize::tools {

struct LabelledPoint {
  render::ChartPoint point;
  std::string label;
};

// name -> points, in the order the names first appeared.
using LabelledGroups = std::vector<std::pair<std::string, std::vector<LabelledPoint>>>;

// A short number for a label or a series name ("0.5", "-2", "1e-09"): printf's %g.
inline std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// One line-and-markers series per group, its points sorted by x (stable: ties keep table order).
inline std::vector<render::ChartSeries> seriesSortedByX(LabelledGroups groups) {
  std::vector<render::ChartSeries> all;
  for (auto& [name, points] : groups) {
    std::stable_sort(points.begin(), points.end(),
                     [](const auto& a, const auto& b) { return a.point.x < b.point.x; });
    render::ChartSeries series{name, {}, render::SeriesStyle::LineAndMarkers, {}};
    for (const LabelledPoint& p : points) {
      series.points.push_back(p.point);
      series.point_labels.push_back(p.label);
    }
    all.push_back(series);
  }
  return all;
}

}  // namespace baize::tools
