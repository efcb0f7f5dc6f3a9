// What `baize calibrate` reports about a fit: the text for people, the JSON object for programs
// (its fitted values under a scene's physics.cushion and physics.cloth keys). Its chart is drawn
// by pictures/calibration_chart.h.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "engine/fit/cushion_calibration.h"

namespace baize::tools {

// Points listed one by one up to this many; above it the largest residuals only.
inline constexpr int kListedPoints = 30;
inline constexpr int kLargestResidualsShown = 10;

void printCalibration(const engine::CushionCalibration& fit, std::ostream& out);
nlohmann::json calibrationJson(const engine::CushionCalibration& fit);

}  // namespace baize::tools
