#include "tools/baize/picture_commands.h"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/line_chart.h"
#include "tools/baize/pictures/accuracy_chart.h"
#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"
#include "tools/baize/progress.h"
#include "tools/baize/pictures/cushion_charts.h"

namespace baize::tools {
namespace {

// A size that reads well on a screen and in the README; --width and --height change it.
constexpr int kDefaultWidthPx = 960;
constexpr int kDefaultHeightPx = 600;

struct ChartFlags {
  std::string input;  // the sweep directory or the bench CSV
  std::string png_path;
  int width_px = kDefaultWidthPx;
  int height_px = kDefaultHeightPx;
};

// Every chart is checked before any is written, so bad data leaves no PNG behind at all.
void writeCharts(const std::vector<NamedChart>& charts, const std::string& directory,
                 const ChartFlags& flags) {
  for (const NamedChart& named : charts) {
    render::layoutChart(named.chart, flags.width_px, flags.height_px);
  }
  for (const NamedChart& named : charts) {
    const std::string path = (std::filesystem::path(directory) / named.file_name).string();
    render::writeChartPng(named.chart, path, flags.width_px, flags.height_px);
    note(std::cout) << "wrote " << path << '\n';
  }
}

// Chart and size errors from render/ name the chart, the series or the axis; say which flag or
// file.
void withContext(const std::string& context, const std::function<void()>& body) {
  try {
    body();
  } catch (const std::invalid_argument& rejected) {
    const std::string message = rejected.what();
    if (message.rfind("chart width (px)", 0) == 0) {
      throw UsageError(namingTheFlag(message, "chart width (px)", "--width"));
    }
    if (message.rfind("chart height (px)", 0) == 0) {
      throw UsageError(namingTheFlag(message, "chart height (px)", "--height"));
    }
    // CSV errors name their file already; messages about a chart's data or axes name the chart or
    // the axis, not the file the data came from.
    if (message.rfind(context, 0) == 0) throw;
    throw UsageError(context + ": " + message);
  }
}

CLI::App* addSizeFlags(CLI::App* command, ChartFlags& flags) {
  command->add_option("--width", flags.width_px, "image width (px)")->capture_default_str();
  command->add_option("--height", flags.height_px, "image height (px)")->capture_default_str();
  return command;
}

// `chart NAME CSV --png OUT.png`: the chart `make` draws from one bench table.
void addCsvChartCommand(CLI::App* chart, const std::string& name, const std::string& description,
                        render::LineChart (*make)(const std::string& csv_path)) {
  auto flags = std::make_shared<ChartFlags>();
  CLI::App* command = chart->add_subcommand(name, description);
  command->add_option("CSV", flags->input, "the bench table")->required();
  command->add_option("--png", flags->png_path, "the PNG file to write")
      ->required()
      ->check(notEmpty());
  addSizeFlags(command, *flags);
  command->callback([flags, name, make] {
    const int status = runReportingErrors("chart " + name, [&] {
      checkOutputPath("--png", flags->png_path);  // parents made; no PNG can go there: refused
      withContext(flags->input, [&] {
        const std::filesystem::path png(flags->png_path);
        writeCharts({{png.filename().string(), make(flags->input)}}, png.parent_path().string(),
                    *flags);
      });
    });
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace

void addChartCommand(CLI::App& parent) {
  CLI::App* chart = parent.add_subcommand(
      "chart",
      "Draw PNG charts of the cushion sweep and the cushion and accuracy bench CSV files (see "
      "docs/cushion.md)");
  chart->require_subcommand(1, 1);

  auto sweep_flags = std::make_shared<ChartFlags>();
  CLI::App* sweep = chart->add_subcommand(
      "sweep",
      "From DIR/fig6.csv ... fig10.csv (baize cushion --sweep DIR) write "
      "DIR/fig6-rebound-speed.png, "
      "fig6-rebound-angle.png, ... fig10-slip-speed.png, fig10-slip-angle.png");
  sweep->add_option("DIR", sweep_flags->input, "the sweep directory")->required();
  addSizeFlags(sweep, *sweep_flags);
  sweep->callback([sweep_flags] {
    const ChartFlags& flags = *sweep_flags;
    const int status = runReportingErrors("chart sweep", [&] {
      withContext(flags.input,
                  [&] { writeCharts(cushionSweepCharts(flags.input), flags.input, flags); });
    });
    if (status != 0) throw CLI::RuntimeError(status);
  });

  addCsvChartCommand(chart, "bench-cushion",
                     "From a `baize bench cushion --csv` table write a log-log chart of median time "
                     "per impact against largest error, one line per solver",
                     cushionBenchChart);
  addCsvChartCommand(chart, "bench-accuracy",
                     "From a `baize bench accuracy --csv` table write a log-log chart of position "
                     "error against median run time per shot, one line per engine (an error of 0 "
                     "drawn on a floor)",
                     benchAccuracyChart);
}

}  // namespace baize::tools
