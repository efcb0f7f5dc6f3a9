// Line charts as PNG images, drawn with Cairo (text with Cairo's own text API in DejaVu Sans):
// a title, two labelled axes (linear or logarithmic) with ticks and a light grid, one or more
// series of points drawn as lines and/or markers in palette colours, and a legend.
//
// layoutChart() exposes where everything goes (the plot area and each axis's data -> pixel
// mapping) so that a caller or a test can tell which pixel a data point lands on.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/chart_axis.h"

namespace baize::render {

struct ChartPoint {
  double x = 0;
  double y = 0;
};

enum class SeriesStyle { Line, Markers, LineAndMarkers };

struct ChartSeries {
  std::string name;                // shown in the legend
  std::vector<ChartPoint> points;  // drawn in this order; a line joins consecutive points
  SeriesStyle style = SeriesStyle::Line;
  // Optional text next to each point (e.g. a solver setting); empty, or one entry per point
  // (an empty entry draws nothing).
  std::vector<std::string> point_labels;
};

enum class LegendPlacement { TopRight, TopLeft, BottomRight, BottomLeft, OutsideRight, None };

struct LineChart {
  std::string title;
  std::string x_label;
  std::string y_label;
  AxisScale x_scale = AxisScale::Linear;
  AxisScale y_scale = AxisScale::Linear;
  std::vector<ChartSeries> series;  // series i is drawn in paletteColour(i)
  LegendPlacement legend = LegendPlacement::TopRight;
};

struct Colour {
  std::uint8_t red = 0;
  std::uint8_t green = 0;
  std::uint8_t blue = 0;
  bool operator==(const Colour& other) const {
    return red == other.red && green == other.green && blue == other.blue;
  }
  bool operator!=(const Colour& other) const { return !(*this == other); }
};

// The colour of series i: a colour-blind-safe palette (Okabe & Ito), repeating after its end.
Colour paletteColour(int series_index);

// Image size limits, px: below the minimum the margins leave no plot; above the maximum Cairo
// cannot make the surface (its limit is 32767) and nobody needs it.
constexpr int kMinChartSidePx = 200;
constexpr int kMaxChartSidePx = 8192;

// Where the chart's parts go in an image of the given size (pixels, origin top left, y down).
struct ChartLayout {
  double plot_left_px = 0;  // the plot area: the axes' frame
  double plot_top_px = 0;
  double plot_right_px = 0;
  double plot_bottom_px = 0;
  AxisTicks x_ticks;
  AxisTicks y_ticks;
  // Data -> pixel column and row. The axes' ends map a few pixels inside the plot area's frame.
  AxisMapping x_to_pixel{AxisTicks{}, 0, 1};
  AxisMapping y_to_pixel{AxisTicks{}, 1, 0};
};

// Checks the chart and the size (std::invalid_argument with a message naming the series and the
// point: no series, a series with no points, a non-finite coordinate, a value <= 0 on a log
// axis, point labels not matching the points, a size outside [kMinChartSidePx, kMaxChartSidePx])
// and returns where its parts go.
ChartLayout layoutChart(const LineChart& chart, int width_px, int height_px);

// The chart as PNG file bytes; the same chart and size give the same bytes.
std::string chartPngBytes(const LineChart& chart, int width_px, int height_px);

// Writes the PNG to `path` whole or not at all (a temporary "<path>.tmp" renamed into place).
// Throws std::invalid_argument for a bad chart or size (before touching the file system) and
// std::runtime_error when the file cannot be written.
void writeChartPng(const LineChart& chart, const std::string& path, int width_px, int height_px);

}  // namespace baize::render
