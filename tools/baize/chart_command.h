// `baize chart`: PNG charts of the cushion model's CSV outputs (render/line_chart, Cairo):
//   baize chart sweep DIR                      the figure families of `baize cushion --sweep DIR`
//   baize chart bench-cushion CSV --png OUT    time against error from `baize bench cushion --csv`
// Reading CSV files rather than rerunning the model keeps a chart reproducible from the table it
// shows. docs/cushion.md describes the charts.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

void addChartCommand(CLI::App& parent);

}  // namespace baize::tools
