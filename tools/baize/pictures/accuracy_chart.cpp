#include "tools/baize/pictures/accuracy_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/io/csv_table.h"
#include "tools/baize/pictures/labelled_series.h"

namespace baize::tools {
namespace {

// The floor for zero errors when the table has no positive error at all, m: far below anything a
// position on a table means.
constexpr double kFloorWithoutPositiveErrors_m = 1e-9;

}  // namespace

render::LineChart benchAccuracyChart(const std::string& csv_path) {
  const engine::CsvTable table = engine::CsvTable::read(csv_path);
  const size_t engine = table.column("engine");
  const size_t setting = table.column("setting");
  const size_t time = table.column("median_us");
  const size_t error = table.column("position_error_m");
  const bool has_subset = table.hasColumn("shots");
  const size_t subset = has_subset ? table.column("shots") : 0;
  if (table.rowCount() == 0) {
    throw std::invalid_argument(csv_path + ": no data rows: it must hold the bench's table");
  }
  double smallest_positive_m = INFINITY;
  for (size_t row = 0; row < table.rowCount(); ++row) {
    const double e = table.number(row, error);
    if (e < 0) {
      throw std::invalid_argument(csv_path + " line " + std::to_string(row + 2) +
                                  ", column position_error_m = " + shortNumber(e) +
                                  " is not allowed: an error is >= 0");
    }
    if (e > 0) smallest_positive_m = std::min(smallest_positive_m, e);
  }
  const double floor_m = std::isfinite(smallest_positive_m)
                             ? std::pow(10.0, std::floor(std::log10(smallest_positive_m)) - 1)
                             : kFloorWithoutPositiveErrors_m;

  render::LineChart chart;
  chart.title = "Whole shots: position error against run time";
  chart.x_label = "median run time per shot (us)";
  chart.y_label = "mean final-position error (m); error 0 drawn at " + shortNumber(floor_m);
  chart.x_scale = render::AxisScale::Log;
  chart.y_scale = render::AxisScale::Log;
  chart.legend = render::LegendPlacement::OutsideRight;
  LabelledGroups engines;  // in table order
  bool floor_labelled = false;
  for (size_t row = 0; row < table.rowCount(); ++row) {
    // One series per engine and subset of shots ("all" needs no mention).
    std::string name = table.text(row, engine);
    if (has_subset && table.text(row, subset) != "all")
      name += " (" + table.text(row, subset) + ")";
    auto found = std::find_if(engines.begin(), engines.end(),
                              [&](const auto& entry) { return entry.first == name; });
    if (found == engines.end()) found = engines.insert(engines.end(), {name, {}});
    const double e = table.number(row, error);
    const std::string& name_of_setting = table.text(row, setting);
    std::string label = name_of_setting;
    if (e == 0) {
      label = name_of_setting == "exact" ? "exact (0)" : name_of_setting + ": error 0";
      // Zero-error points of several subsets sit on the floor side by side: label the first only.
      if (floor_labelled) label.clear();
      floor_labelled = true;
    }
    found->second.push_back({{table.number(row, time), e > 0 ? e : floor_m}, label});
  }
  for (render::ChartSeries& series : seriesSortedByX(std::move(engines)))
    chart.series.push_back(std::move(series));
  return chart;
}

}  // namespace baize::tools
