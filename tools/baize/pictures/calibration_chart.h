// `baize calibrate --png`: the chart of measured against fitted rebound speeds, one marker per
// impact and the line where they are equal.
#pragma once

#include <string>

#include "engine/fit/cushion_calibration.h"
#include "render/line_chart.h"

namespace baize::tools {

// The chart's size: as `baize chart` draws.
constexpr int kCalibrationChartWidth_px = 960;
constexpr int kCalibrationChartHeight_px = 600;

render::LineChart calibrationChart(const engine::CushionCalibration& fit);

// The chart as a PNG at `path`, written whole.
void writeCalibrationChart(const engine::CushionCalibration& fit, const std::string& path);

}  // namespace baize::tools
