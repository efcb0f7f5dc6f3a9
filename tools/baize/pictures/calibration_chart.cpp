#include "tools/baize/pictures/calibration_chart.h"

#include <algorithm>

namespace baize::tools {

render::LineChart calibrationChart(const engine::CushionCalibration& fit) {
  render::LineChart chart;
  chart.title = "Cushion rebound: measured and fitted";
  chart.x_label = "measured rebound speed (m/s)";
  chart.y_label = "fitted rebound speed (m/s)";
  chart.legend = render::LegendPlacement::TopLeft;
  render::ChartSeries points{"impacts", {}, render::SeriesStyle::Markers, {}};
  double most = 0;
  for (const engine::CalibratedPoint& p : fit.points) {
    points.points.push_back({p.measured.rebound_speed_mps, p.fitted_speed_mps});
    most = std::max({most, p.measured.rebound_speed_mps, p.fitted_speed_mps});
  }
  chart.series.push_back({"fitted = measured", {{0, 0}, {most, most}}, render::SeriesStyle::Line, {}});
  chart.series.push_back(points);
  return chart;
}

void writeCalibrationChart(const engine::CushionCalibration& fit, const std::string& path) {
  render::writeChartPng(calibrationChart(fit), path, kCalibrationChartWidth_px,
                        kCalibrationChartHeight_px);
}

}  // namespace baize::tools
