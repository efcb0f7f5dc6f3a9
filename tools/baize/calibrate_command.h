// `baize calibrate DATA.csv`: fits the cushion model's parameters to measured impacts
// (engine/fit/cushion_calibration.h) and reports them with their uncertainties, the residuals and,
// on request, a chart and a JSON file. See docs/calibrate.md.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

class Drawing;

// `drawing` makes its pictures; null in a build without rendering (picture_commands.h).
void addCalibrateCommand(CLI::App& parent, const Drawing* drawing);

}  // namespace baize::tools
