#include "render/line_chart.h"

#include <cairo.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "physics/value_text.h"
#include "engine/io/whole_file.h"

namespace baize::render {
namespace {

// Okabe & Ito's palette minus its yellow, which is unreadable on white; then black.
constexpr Colour kPalette[] = {
    {0x00, 0x72, 0xB2},  // blue
    {0xD5, 0x5E, 0x00},  // vermillion
    {0x00, 0x9E, 0x73},  // bluish green
    {0xCC, 0x79, 0xA7},  // reddish purple
    {0xE6, 0x9F, 0x00},  // orange
    {0x56, 0xB4, 0xE9},  // sky blue
    {0x00, 0x00, 0x00},  // black
};
constexpr int kPaletteSize = sizeof kPalette / sizeof kPalette[0];

constexpr double kPi = 3.14159265358979323846;

constexpr const char* kFontFamily = "DejaVu Sans";  // fonts-dejavu-core; see tools/setup.sh

// Sizes relative to the image, so a larger image is a scaled-up chart rather than a smaller one.
constexpr double kFontPxPerImagePx = 1.0 / 48;  // tick label font size per px of the short side
constexpr double kMinFontPx = 10;               // smaller text is unreadable
constexpr double kMaxFontPx = 28;
constexpr double kTitleFontScale = 1.3;
constexpr double kLineHeightPerFontPx =
    1.2;  // a line of text with its leading  // title font size / tick label font size
constexpr double kMinLineWidthPx = 2;  // series lines: >= 2 px cover whole pixel rows
constexpr double kLineWidthPerImagePx = 1.0 / 320;
constexpr double kMarkerRadiusPerLineWidth = 1.6;
constexpr double kTickLengthPx = 5;
// The axes' ends sit this far inside the frame, so that data at the ends of the range (which the
// ticks often meet exactly) is drawn clear of the frame rather than under it.
constexpr double kDataInsetPerFontPx = 0.6;
constexpr double kGapPerFontPx = 0.5;  // space between text and what it labels, per font px
constexpr double kLegendSwatchPerFontPx = 2.2;  // length of a legend entry's line sample
constexpr double kLegendRowPerFontPx = 1.5;     // legend line spacing

// About one labelled tick per this many pixels of axis: labels stay apart at any size.
constexpr double kPxPerXTick = 90;
constexpr double kPxPerYTick = 70;
constexpr int kMinTickTarget = 2;
constexpr int kMaxTickTarget = 10;

constexpr double kGridGrey = 0.88;  // grid lines, light enough to stay behind the data
constexpr double kFrameGrey = 0.0;
constexpr double kLegendBorderGrey = 0.6;

struct CairoDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
  void operator()(cairo_t* context) const { cairo_destroy(context); }
};
using Surface = std::unique_ptr<cairo_surface_t, CairoDeleter>;
using Context = std::unique_ptr<cairo_t, CairoDeleter>;

// The text settings fixed rather than taken from the machine's fontconfig defaults, so the same
// chart gives the same pixels everywhere the same Cairo and font are installed.
void setFont(cairo_t* cr, double size_px) {
  cairo_select_font_face(cr, kFontFamily, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, options);
  cairo_font_options_destroy(options);
}

double textWidth(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

struct TextMetrics {
  double ascent = 0;
  double height = 0;  // ascent + descent
};

TextMetrics fontMetrics(cairo_t* cr) {
  cairo_font_extents_t extents;
  cairo_font_extents(cr, &extents);
  return {extents.ascent, extents.ascent + extents.descent};
}

std::string chartName(const LineChart& chart) { return "chart '" + chart.title + "'"; }

[[noreturn]] void rejectPoint(const LineChart& chart, const ChartSeries& series, size_t index,
                              const char* axis, double value, const std::string& allowed) {
  throw std::invalid_argument(chartName(chart) + ": series '" + series.name + "' point " +
                              std::to_string(index) + " (counting from 0) has " + axis + " = " +
                              physics::valueText(value) + ", which is not allowed: " + allowed);
}

void validateChart(const LineChart& chart) {
  if (chart.series.empty()) {
    throw std::invalid_argument(chartName(chart) + " has no series: it needs at least one");
  }
  for (const ChartSeries& series : chart.series) {
    if (series.points.empty()) {
      throw std::invalid_argument(chartName(chart) + ": series '" + series.name +
                                  "' has no points: a series needs at least one");
    }
    if (!series.point_labels.empty() && series.point_labels.size() != series.points.size()) {
      throw std::invalid_argument(chartName(chart) + ": series '" + series.name + "' has " +
                                  std::to_string(series.point_labels.size()) +
                                  " point labels for " + std::to_string(series.points.size()) +
                                  " points: give none or one per point");
    }
    for (size_t i = 0; i < series.points.size(); ++i) {
      const ChartPoint& p = series.points[i];
      if (!std::isfinite(p.x)) rejectPoint(chart, series, i, "x", p.x, "it must be finite");
      if (!std::isfinite(p.y)) rejectPoint(chart, series, i, "y", p.y, "it must be finite");
      if (chart.x_scale == AxisScale::Log && !(p.x > 0)) {
        rejectPoint(chart, series, i, "x", p.x, "the x axis is logarithmic, so it must be > 0");
      }
      if (chart.y_scale == AxisScale::Log && !(p.y > 0)) {
        rejectPoint(chart, series, i, "y", p.y, "the y axis is logarithmic, so it must be > 0");
      }
    }
  }
}

void validateSize(int width_px, int height_px) {
  const std::string allowed = "it must lie in [" + std::to_string(kMinChartSidePx) + ", " +
                              std::to_string(kMaxChartSidePx) + "]";
  if (width_px < kMinChartSidePx || width_px > kMaxChartSidePx) {
    physics::rejectValue("chart width (px)", width_px, allowed);
  }
  if (height_px < kMinChartSidePx || height_px > kMaxChartSidePx) {
    physics::rejectValue("chart height (px)", height_px, allowed);
  }
}

AxisTicks ticksFor(AxisScale scale, double low, double high, double axis_length_px,
                   double px_per_tick) {
  const int target =
      std::clamp(static_cast<int>(axis_length_px / px_per_tick), kMinTickTarget, kMaxTickTarget);
  return scale == AxisScale::Log ? logTicks(low, high, target) : linearTicks(low, high, target);
}

// Sizes that follow from the image size; shared by the layout and the drawing.
struct Metrics {
  double font_px;
  double title_font_px;
  double line_width_px;
  double gap_px;
};

Metrics metricsFor(int width_px, int height_px) {
  Metrics m;
  const double short_side = std::min(width_px, height_px);
  m.font_px = std::clamp(short_side * kFontPxPerImagePx, kMinFontPx, kMaxFontPx);
  m.title_font_px = m.font_px * kTitleFontScale;
  m.line_width_px = std::max(kMinLineWidthPx, short_side * kLineWidthPerImagePx);
  m.gap_px = m.font_px * kGapPerFontPx;
  return m;
}

double legendWidth(cairo_t* cr, const LineChart& chart, const Metrics& m) {
  double widest = 0;
  for (const ChartSeries& series : chart.series)
    widest = std::max(widest, textWidth(cr, series.name));
  return m.gap_px + m.font_px * kLegendSwatchPerFontPx + m.gap_px + widest + m.gap_px;
}

double legendHeight(const LineChart& chart, const Metrics& m) {
  return m.gap_px * 2 + chart.series.size() * m.font_px * kLegendRowPerFontPx;
}

// The layout, measured with the font in `cr` (which the caller has set to the tick font).
ChartLayout layoutWith(cairo_t* cr, const LineChart& chart, int width_px, int height_px) {
  const Metrics m = metricsFor(width_px, height_px);
  double x_low = chart.series[0].points[0].x, x_high = x_low;
  double y_low = chart.series[0].points[0].y, y_high = y_low;
  for (const ChartSeries& series : chart.series) {
    for (const ChartPoint& p : series.points) {
      x_low = std::min(x_low, p.x);
      x_high = std::max(x_high, p.x);
      y_low = std::min(y_low, p.y);
      y_high = std::max(y_high, p.y);
    }
  }
  const TextMetrics tick_text = fontMetrics(cr);
  ChartLayout layout;
  // The tick counts follow the image size (the plot is most of it), which breaks the circle of
  // the left margin depending on the y labels.
  layout.x_ticks = ticksFor(chart.x_scale, x_low, x_high, width_px, kPxPerXTick);
  layout.y_ticks = ticksFor(chart.y_scale, y_low, y_high, height_px, kPxPerYTick);

  double widest_y_label = 0;
  for (const double tick : layout.y_ticks.major) {
    widest_y_label = std::max(widest_y_label, textWidth(cr, tickLabel(layout.y_ticks, tick)));
  }
  const double axis_label_band = chart.y_label.empty() ? 0 : tick_text.height + m.gap_px;
  layout.plot_left_px =
      std::round(m.gap_px + axis_label_band + widest_y_label + m.gap_px + kTickLengthPx);
  const double x_label_band = chart.x_label.empty() ? 0 : tick_text.height + m.gap_px;
  layout.plot_bottom_px = std::round(
      height_px - (m.gap_px + x_label_band + tick_text.height + m.gap_px + kTickLengthPx));
  double top = m.gap_px;
  if (!chart.title.empty()) top += m.title_font_px * kLineHeightPerFontPx + m.gap_px;
  // Half a label's height above the top tick, so its label is not cut off.
  layout.plot_top_px = std::round(std::max(top, tick_text.height));
  double right_margin = std::max(
      m.gap_px * 2, textWidth(cr, tickLabel(layout.x_ticks, layout.x_ticks.high)) / 2 + m.gap_px);
  if (chart.legend == LegendPlacement::OutsideRight) {
    right_margin = m.gap_px * 2 + legendWidth(cr, chart, m) + m.gap_px;  // gap, legend, gap
  }
  layout.plot_right_px = std::round(width_px - right_margin);
  if (layout.plot_right_px - layout.plot_left_px < m.font_px * 4 ||
      layout.plot_bottom_px - layout.plot_top_px < m.font_px * 4) {
    throw std::invalid_argument(chartName(chart) + ": a " + std::to_string(width_px) + " x " +
                                std::to_string(height_px) +
                                " px image leaves no room for the plot beside its labels and "
                                "legend: make it larger");
  }
  const double inset = std::round(m.font_px * kDataInsetPerFontPx);
  layout.x_to_pixel =
      AxisMapping(layout.x_ticks, layout.plot_left_px + inset, layout.plot_right_px - inset);
  layout.y_to_pixel =
      AxisMapping(layout.y_ticks, layout.plot_bottom_px - inset, layout.plot_top_px + inset);
  return layout;
}

void setColour(cairo_t* cr, const Colour& c) {
  cairo_set_source_rgb(cr, c.red / 255.0, c.green / 255.0, c.blue / 255.0);
}

// The centre of pixel row/column `px` (a 1 px line there covers exactly one pixel).
double onPixel(double px) { return std::floor(px) + 0.5; }

void showText(cairo_t* cr, const std::string& text, double x, double baseline_y) {
  cairo_move_to(cr, x, baseline_y);
  cairo_show_text(cr, text.c_str());
}

void drawMarker(cairo_t* cr, double x, double y, double radius) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, x, y, radius, 0, 2 * kPi);
  cairo_fill(cr);
}

void drawGridAndTicks(cairo_t* cr, const ChartLayout& layout) {
  cairo_set_line_width(cr, 1);
  cairo_set_source_rgb(cr, kGridGrey, kGridGrey, kGridGrey);
  for (const double tick : layout.x_ticks.major) {
    const double x = onPixel(layout.x_to_pixel.toPixel(tick));
    cairo_move_to(cr, x, layout.plot_top_px);
    cairo_line_to(cr, x, layout.plot_bottom_px);
  }
  for (const double tick : layout.y_ticks.major) {
    const double y = onPixel(layout.y_to_pixel.toPixel(tick));
    cairo_move_to(cr, layout.plot_left_px, y);
    cairo_line_to(cr, layout.plot_right_px, y);
  }
  cairo_stroke(cr);

  cairo_set_source_rgb(cr, kFrameGrey, kFrameGrey, kFrameGrey);
  const auto xTicks = [&](const std::vector<double>& ticks, double length) {
    for (const double tick : ticks) {
      const double x = onPixel(layout.x_to_pixel.toPixel(tick));
      cairo_move_to(cr, x, onPixel(layout.plot_bottom_px));
      cairo_line_to(cr, x, onPixel(layout.plot_bottom_px) + length);
    }
  };
  const auto yTicks = [&](const std::vector<double>& ticks, double length) {
    for (const double tick : ticks) {
      const double y = onPixel(layout.y_to_pixel.toPixel(tick));
      cairo_move_to(cr, onPixel(layout.plot_left_px), y);
      cairo_line_to(cr, onPixel(layout.plot_left_px) - length, y);
    }
  };
  xTicks(layout.x_ticks.major, kTickLengthPx);
  xTicks(layout.x_ticks.minor, kTickLengthPx / 2);
  yTicks(layout.y_ticks.major, kTickLengthPx);
  yTicks(layout.y_ticks.minor, kTickLengthPx / 2);
  cairo_rectangle(cr, onPixel(layout.plot_left_px), onPixel(layout.plot_top_px),
                  std::floor(layout.plot_right_px) - std::floor(layout.plot_left_px),
                  std::floor(layout.plot_bottom_px) - std::floor(layout.plot_top_px));
  cairo_stroke(cr);
}

void drawTickLabels(cairo_t* cr, const ChartLayout& layout, const Metrics& m) {
  const TextMetrics text = fontMetrics(cr);
  for (const double tick : layout.x_ticks.major) {
    const std::string label = tickLabel(layout.x_ticks, tick);
    showText(cr, label, layout.x_to_pixel.toPixel(tick) - textWidth(cr, label) / 2,
             layout.plot_bottom_px + kTickLengthPx + m.gap_px + text.ascent);
  }
  for (const double tick : layout.y_ticks.major) {
    const std::string label = tickLabel(layout.y_ticks, tick);
    // Centred on the tick: digits stand about 0.76 ascent tall, so the baseline goes 0.38 below.
    showText(cr, label, layout.plot_left_px - kTickLengthPx - m.gap_px - textWidth(cr, label),
             layout.y_to_pixel.toPixel(tick) + text.ascent * 0.38);
  }
}

void drawAxisLabelsAndTitle(cairo_t* cr, const LineChart& chart, const ChartLayout& layout,
                            const Metrics& m, int width_px, int height_px) {
  const TextMetrics text = fontMetrics(cr);
  const double plot_centre_x = (layout.plot_left_px + layout.plot_right_px) / 2;
  const double plot_centre_y = (layout.plot_top_px + layout.plot_bottom_px) / 2;
  if (!chart.x_label.empty()) {
    showText(cr, chart.x_label, plot_centre_x - textWidth(cr, chart.x_label) / 2,
             height_px - m.gap_px - (text.height - text.ascent));
  }
  if (!chart.y_label.empty()) {
    cairo_save(cr);
    cairo_translate(cr, m.gap_px + text.ascent, plot_centre_y + textWidth(cr, chart.y_label) / 2);
    cairo_rotate(cr, -kPi / 2);
    showText(cr, chart.y_label, 0, 0);
    cairo_restore(cr);
  }
  if (!chart.title.empty()) {
    setFont(cr, m.title_font_px);
    // A title wider than the image is shrunk to fit rather than cut off.
    const double room_px = width_px - 2 * m.gap_px;
    const double full_width_px = textWidth(cr, chart.title);
    if (full_width_px > room_px) setFont(cr, m.title_font_px * room_px / full_width_px);
    const double title_x = std::max(m.gap_px, width_px / 2.0 - textWidth(cr, chart.title) / 2);
    showText(cr, chart.title, title_x, m.gap_px + fontMetrics(cr).ascent);
    setFont(cr, m.font_px);
  }
}

void drawSeries(cairo_t* cr, const LineChart& chart, const ChartLayout& layout, const Metrics& m) {
  cairo_save(cr);
  cairo_rectangle(cr, layout.plot_left_px, layout.plot_top_px,
                  layout.plot_right_px - layout.plot_left_px,
                  layout.plot_bottom_px - layout.plot_top_px);
  cairo_clip(cr);
  cairo_set_line_width(cr, m.line_width_px);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (size_t s = 0; s < chart.series.size(); ++s) {
    const ChartSeries& series = chart.series[s];
    setColour(cr, paletteColour(static_cast<int>(s)));
    if (series.style != SeriesStyle::Markers) {
      for (size_t i = 0; i < series.points.size(); ++i) {
        const double x = layout.x_to_pixel.toPixel(series.points[i].x);
        const double y = layout.y_to_pixel.toPixel(series.points[i].y);
        if (i == 0) {
          cairo_move_to(cr, x, y);
        } else {
          cairo_line_to(cr, x, y);
        }
      }
      cairo_stroke(cr);
    }
    if (series.style != SeriesStyle::Line) {
      for (const ChartPoint& p : series.points) {
        drawMarker(cr, layout.x_to_pixel.toPixel(p.x), layout.y_to_pixel.toPixel(p.y),
                   m.line_width_px * kMarkerRadiusPerLineWidth);
      }
    }
  }
  cairo_restore(cr);
  // Point labels may run past the plot's edge into the margin: not clipped. They go above and
  // below their points by turns, so neighbouring points' labels do not overlap.
  const TextMetrics text = fontMetrics(cr);
  for (size_t s = 0; s < chart.series.size(); ++s) {
    const ChartSeries& series = chart.series[s];
    setColour(cr, paletteColour(static_cast<int>(s)));
    for (size_t i = 0; i < series.point_labels.size(); ++i) {
      const double y = layout.y_to_pixel.toPixel(series.points[i].y);
      showText(cr, series.point_labels[i], layout.x_to_pixel.toPixel(series.points[i].x) + m.gap_px,
               i % 2 == 0 ? y - m.gap_px : y + m.gap_px + text.ascent);
    }
  }
}

void drawLegend(cairo_t* cr, const LineChart& chart, const ChartLayout& layout, const Metrics& m) {
  if (chart.legend == LegendPlacement::None) return;
  const double width = legendWidth(cr, chart, m);
  const double height = legendHeight(chart, m);
  const double inset = m.gap_px;  // from the plot's frame
  double left = layout.plot_right_px - inset - width;
  double top = layout.plot_top_px + inset;
  switch (chart.legend) {
    case LegendPlacement::TopLeft:
      left = layout.plot_left_px + inset;
      break;
    case LegendPlacement::BottomRight:
      top = layout.plot_bottom_px - inset - height;
      break;
    case LegendPlacement::BottomLeft:
      left = layout.plot_left_px + inset;
      top = layout.plot_bottom_px - inset - height;
      break;
    case LegendPlacement::OutsideRight:
      left = layout.plot_right_px + m.gap_px * 2;
      top = layout.plot_top_px;
      break;
    default:
      break;
  }
  left = std::round(left);
  top = std::round(top);
  cairo_rectangle(cr, left + 0.5, top + 0.5, std::round(width), std::round(height));
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_fill_preserve(cr);
  cairo_set_line_width(cr, 1);
  cairo_set_source_rgb(cr, kLegendBorderGrey, kLegendBorderGrey, kLegendBorderGrey);
  cairo_stroke(cr);

  const TextMetrics text = fontMetrics(cr);
  const double row_px = m.font_px * kLegendRowPerFontPx;
  const double swatch_px = m.font_px * kLegendSwatchPerFontPx;
  for (size_t s = 0; s < chart.series.size(); ++s) {
    const ChartSeries& series = chart.series[s];
    const double middle_y = top + m.gap_px + row_px * (s + 0.5);
    const double swatch_left = left + m.gap_px;
    setColour(cr, paletteColour(static_cast<int>(s)));
    if (series.style != SeriesStyle::Markers) {
      cairo_set_line_width(cr, m.line_width_px);
      cairo_move_to(cr, swatch_left, middle_y);
      cairo_line_to(cr, swatch_left + swatch_px, middle_y);
      cairo_stroke(cr);
    }
    if (series.style != SeriesStyle::Line) {
      drawMarker(cr, swatch_left + swatch_px / 2, middle_y,
                 m.line_width_px * kMarkerRadiusPerLineWidth);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    showText(cr, series.name, swatch_left + swatch_px + m.gap_px,
             middle_y - text.height / 2 + text.ascent);
  }
}

void checkCairo(cairo_status_t status, const std::string& what) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(what + ": " + cairo_status_to_string(status));
  }
}

cairo_status_t appendToString(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Colour paletteColour(int series_index) {
  if (series_index < 0) physics::rejectValue("series index", series_index, "it must be >= 0");
  return kPalette[series_index % kPaletteSize];
}

ChartLayout layoutChart(const LineChart& chart, int width_px, int height_px) {
  validateSize(width_px, height_px);
  validateChart(chart);
  // A scratch surface to measure text with the same font settings as the drawing.
  const Surface scratch(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1));
  const Context cr(cairo_create(scratch.get()));
  setFont(cr.get(), metricsFor(width_px, height_px).font_px);
  return layoutWith(cr.get(), chart, width_px, height_px);
}

std::string chartPngBytes(const LineChart& chart, int width_px, int height_px) {
  const ChartLayout layout = layoutChart(chart, width_px, height_px);
  const Metrics m = metricsFor(width_px, height_px);
  // RGB24: an opaque image, so pixels are plain colours (no premultiplied alpha).
  const Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width_px, height_px));
  checkCairo(cairo_surface_status(surface.get()), chartName(chart) + ": cannot make the image");
  const Context context(cairo_create(surface.get()));
  cairo_t* cr = context.get();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  setFont(cr, m.font_px);
  drawGridAndTicks(cr, layout);
  drawSeries(cr, chart, layout, m);
  cairo_set_source_rgb(cr, 0, 0, 0);
  drawTickLabels(cr, layout, m);
  drawAxisLabelsAndTitle(cr, chart, layout, m, width_px, height_px);
  drawLegend(cr, chart, layout, m);
  checkCairo(cairo_status(cr), chartName(chart) + ": drawing failed");
  cairo_surface_flush(surface.get());
  std::string png;
  checkCairo(cairo_surface_write_to_png_stream(surface.get(), appendToString, &png),
             chartName(chart) + ": PNG encoding failed");
  return png;
}

void writeChartPng(const LineChart& chart, const std::string& path, int width_px, int height_px) {
  const std::string png = chartPngBytes(chart, width_px, height_px);
  const engine::WholeFileTarget target = engine::wholeFileTarget(path);
  const std::string written = target.stream ? target.path : engine::temporaryFor(target);
  const auto fail = [&](const std::string& what) {
    const std::string reason = errno != 0 ? std::string(": ") + std::strerror(errno) : "";
    if (!target.stream) std::remove(written.c_str());
    throw std::runtime_error("cannot write the chart '" + path + "': " + what + reason);
  };
  errno = 0;
  std::ofstream out(written, std::ios::binary | (target.stream ? std::ios::app : std::ios::trunc));
  if (!out) fail("cannot create '" + written + "'");
  out.write(png.data(), static_cast<std::streamsize>(png.size()));
  out.close();
  if (out.fail()) fail("cannot write '" + written + "'");
  // std::rename replaces an existing file atomically on POSIX systems.
  if (!target.stream && std::rename(written.c_str(), target.path.c_str()) != 0)
    fail("cannot rename '" + written + "'");
}

}  // namespace baize::render
