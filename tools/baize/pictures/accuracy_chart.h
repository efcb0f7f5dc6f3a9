// The chart of a `baize bench accuracy --csv` table: position error against run time, log-log,
// one series per engine, each point labelled with its setting. Used by `baize chart`.
#pragma once

#include <string>

#include "render/line_chart.h"

namespace baize::tools {

// From the table (engine,setting,median_us,position_error_m,outcome_mismatch[,shots]): x the
// median run time per shot (us), y the mean position error (m), both logarithmic; one series per
// engine and value of "shots" (the subset of the set a row scores: "all", "no-breaks"). An error
// of exactly 0 (the event loop, the reference) has no place on a log axis: it is drawn on a floor
// one decade below the smallest positive error in the table, rounded down to a power of ten (1e-9
// m when there is none); the first such point is labelled "exact (0)" (or "<setting>: error 0"),
// and the y axis's title names the floor. Throws std::invalid_argument naming the file for a
// missing file or column, a bad value or a negative error.
render::LineChart benchAccuracyChart(const std::string& csv_path);

}  // namespace baize::tools
