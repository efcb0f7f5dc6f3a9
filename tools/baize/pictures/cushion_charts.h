// Charts of the cushion model's CSV outputs: the paper's figure families from a `baize cushion
// --sweep` directory, and time against error from a `baize bench cushion --csv` table. Used by
// `baize chart`.
#pragma once

#include <string>
#include <vector>

#include "render/line_chart.h"

namespace baize::tools {

struct NamedChart {
  std::string file_name;  // e.g. "fig6-rebound-speed.png"
  render::LineChart chart;
};

// From DIR/fig6.csv, fig7.csv, fig8.csv and fig10.csv: rebound speed and rebound angle against
// the incidence angle, one series per curve (fig6/7/8-rebound-speed.png, -rebound-angle.png);
// slip speeds and slip directions at both contacts against P (fig10-slip-speed.png,
// fig10-slip-angle.png). Throws std::invalid_argument naming the file for a missing file or
// column or a bad value.
std::vector<NamedChart> cushionSweepCharts(const std::string& directory);

// From the bench table (solver,setting,median_ns,max_error): median time per impact against the
// largest error, log-log, one series per solver, each point labelled with its setting.
render::LineChart cushionBenchChart(const std::string& csv_path);

}  // namespace baize::tools
