#include "tools/baize/pictures/cushion_charts.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "engine/io/csv_table.h"
#include "tools/baize/pictures/labelled_series.h"

namespace baize::tools {
namespace {

// In fig10.csv a contact that sticks has a slip speed of zero or round-off, and atan2 of it gives
// an angle that means nothing; directions are drawn only where the slip exceeds this (m/s), far
// above the solvers' round-off and far below the slips of a slipping contact (0.1 m/s and more).
constexpr double kStuckSlipMps = 1e-6;

struct ReboundFamily {
  const char* figure;        // "fig6": the CSV and the charts' file name stem
  const char* curve_column;  // the column that tells the curves apart
  const char* curve_prefix;  // "V0 = "
  const char* curve_unit;    // " m/s"
  const char* fixed;         // what the family holds fixed, for the title
};

// The families of tools/baize/cushion_sweep.cpp; docs/cushion.md lists their curves.
constexpr ReboundFamily kReboundFamilies[] = {
    {"fig6", "speed_mps", "V0 = ", " m/s", "rolling, no side"},
    {"fig7", "topspin_k", "topspin ", " V0/R", "V0 = 1 m/s, no side"},
    {"fig8", "sidespin_k", "sidespin ", " V0/R", "V0 = 1 m/s, rolling"},
};

std::string csvPath(const std::string& directory, const std::string& figure) {
  return (std::filesystem::path(directory) / (figure + ".csv")).string();
}

// Rows with the same curve value in a run form one curve: the sweep writes curve after curve.
void addReboundCharts(const std::string& directory, const ReboundFamily& family,
                      std::vector<NamedChart>& charts) {
  const engine::CsvTable table = engine::CsvTable::read(csvPath(directory, family.figure));
  const size_t curve = table.column(family.curve_column);
  const size_t alpha = table.column("alpha_deg");
  const size_t speed = table.column("rebound_speed_mps");
  const size_t angle = table.column("rebound_angle_deg");
  if (table.rowCount() == 0) {
    throw std::invalid_argument(table.path() + ": no data rows: it must hold at least one curve");
  }
  render::LineChart speed_chart;
  speed_chart.title = std::string(family.figure) + ": rebound speed (" + family.fixed + ")";
  speed_chart.x_label = "incidence angle α from the cushion line (deg)";
  speed_chart.y_label = "rebound speed (m/s)";
  speed_chart.legend = render::LegendPlacement::OutsideRight;
  render::LineChart angle_chart = speed_chart;
  angle_chart.title = std::string(family.figure) + ": rebound angle (" + family.fixed + ")";
  angle_chart.y_label = "rebound angle from the cushion line (deg)";
  for (size_t row = 0; row < table.rowCount(); ++row) {
    const double value = table.number(row, curve);
    if (row == 0 || value != table.number(row - 1, curve)) {
      const std::string name = family.curve_prefix + shortNumber(value) + family.curve_unit;
      speed_chart.series.push_back({name, {}, render::SeriesStyle::Line, {}});
      angle_chart.series.push_back({name, {}, render::SeriesStyle::Line, {}});
    }
    const double alpha_deg = table.number(row, alpha);
    speed_chart.series.back().points.push_back({alpha_deg, table.number(row, speed)});
    angle_chart.series.back().points.push_back({alpha_deg, table.number(row, angle)});
  }
  charts.push_back({std::string(family.figure) + "-rebound-speed.png", speed_chart});
  charts.push_back({std::string(family.figure) + "-rebound-angle.png", angle_chart});
}

void addSlipCharts(const std::string& directory, std::vector<NamedChart>& charts) {
  const engine::CsvTable table = engine::CsvTable::read(csvPath(directory, "fig10"));
  const size_t impulse = table.column("impulse_Ns");
  const size_t contacts[2][2] = {
      {table.column("cushion_slip_mps"), table.column("cushion_slip_angle_deg")},
      {table.column("cloth_slip_mps"), table.column("cloth_slip_angle_deg")}};
  const char* const names[2][2] = {{"cushion contact I: s", "cushion contact I: Φ"},
                                   {"cloth contact C: s′", "cloth contact C: Φ′"}};
  if (table.rowCount() == 0) {
    throw std::invalid_argument(table.path() + ": no data rows: it must hold the impact's slips");
  }
  const std::string shot = "V0 = 2 m/s, α = 45°, topspin 1.5 V0/R, sidespin 2 V0/R";
  render::LineChart speeds;
  speeds.title = "fig10: slip speeds (" + shot + ")";
  speeds.x_label = "impulse P (N s)";
  speeds.y_label = "slip speed (m/s)";
  speeds.legend = render::LegendPlacement::OutsideRight;
  render::LineChart directions = speeds;
  directions.title = "fig10: slip directions while slipping (" + shot + ")";
  directions.y_label = "slip direction (deg)";
  for (int c = 0; c < 2; ++c) {
    render::ChartSeries speed{names[c][0], {}, render::SeriesStyle::Line, {}};
    // Markers, not lines: a direction is undefined while the contact sticks, and it wraps at
    // +-180 deg; a line would draw jumps that did not happen.
    render::ChartSeries direction{names[c][1], {}, render::SeriesStyle::Markers, {}};
    for (size_t row = 0; row < table.rowCount(); ++row) {
      const double p = table.number(row, impulse);
      const double slip = table.number(row, contacts[c][0]);
      speed.points.push_back({p, slip});
      if (slip > kStuckSlipMps) direction.points.push_back({p, table.number(row, contacts[c][1])});
    }
    speeds.series.push_back(speed);
    // A contact that sticks throughout has no direction to show; the chart says so by its absence.
    if (!direction.points.empty()) directions.series.push_back(direction);
  }
  charts.push_back({"fig10-slip-speed.png", speeds});
  if (!directions.series.empty()) charts.push_back({"fig10-slip-angle.png", directions});
}

}  // namespace

std::vector<NamedChart> cushionSweepCharts(const std::string& directory) {
  std::vector<NamedChart> charts;
  for (const ReboundFamily& family : kReboundFamilies) addReboundCharts(directory, family, charts);
  addSlipCharts(directory, charts);
  return charts;
}

render::LineChart cushionBenchChart(const std::string& csv_path) {
  const engine::CsvTable table = engine::CsvTable::read(csv_path);
  const size_t solver = table.column("solver");
  const size_t setting = table.column("setting");
  const size_t time = table.column("median_ns");
  const size_t error = table.column("max_error");
  render::LineChart chart;
  chart.title = "Cushion solvers: time per impact against largest error";
  chart.x_label = "largest velocity error over the set (V0)";
  chart.y_label = "median time per impact (ns)";
  chart.x_scale = render::AxisScale::Log;
  chart.y_scale = render::AxisScale::Log;
  chart.legend = render::LegendPlacement::TopRight;
  LabelledGroups solvers;  // in table order
  for (size_t row = 0; row < table.rowCount(); ++row) {
    const std::string& name = table.text(row, solver);
    auto found = std::find_if(solvers.begin(), solvers.end(),
                              [&](const auto& entry) { return entry.first == name; });
    if (found == solvers.end()) found = solvers.insert(solvers.end(), {name, {}});
    found->second.push_back(
        {{table.number(row, error), table.number(row, time)}, table.text(row, setting)});
  }
  if (solvers.empty()) {
    throw std::invalid_argument(csv_path + ": no data rows: it must hold the bench's table");
  }
  for (render::ChartSeries& series : seriesSortedByX(std::move(solvers)))
    chart.series.push_back(std::move(series));
  return chart;
}

}  // namespace baize::tools
