#include "render/line_chart.h"

#include <cairo.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "tests/physics/rejection_test_support.h"

namespace baize::render {

// Failures print colours as rgb(r, g, b) (found by argument-dependent lookup, so not in the
// anonymous namespace).
std::ostream& operator<<(std::ostream& out, const Colour& c) {
  return out << "rgb(" << int(c.red) << ", " << int(c.green) << ", " << int(c.blue) << ")";
}

namespace {

using physics::test::expectRejected;
using physics::test::expectValueRejected;

constexpr int kWidthPx = 640;
constexpr int kHeightPx = 400;
// A test pixel this far from a series line shows no trace of it: lines are 2 px wide here, their
// antialiased edge reaches about 1 px further.
constexpr int kClearOfLinePx = 8;

// A decoded PNG: the pixels the chart module wrote, read back through Cairo's PNG reader.
class Image {
 public:
  explicit Image(const std::string& png) : png_(png) {
    surface_ = cairo_image_surface_create_from_png_stream(readChunk, this);
    if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error("not a PNG this test can read");
    }
  }
  ~Image() { cairo_surface_destroy(surface_); }
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  int width() const { return cairo_image_surface_get_width(surface_); }
  int height() const { return cairo_image_surface_get_height(surface_); }
  Colour at(double x_px, double y_px) const {
    const int column = static_cast<int>(std::floor(x_px));
    const int row = static_cast<int>(std::floor(y_px));
    // Cairo's 32-bit pixels are native-endian 0xAARRGGBB.
    const unsigned char* data = cairo_image_surface_get_data(surface_);
    std::uint32_t pixel;
    std::memcpy(&pixel, data + row * cairo_image_surface_get_stride(surface_) + column * 4, 4);
    return {static_cast<std::uint8_t>(pixel >> 16), static_cast<std::uint8_t>(pixel >> 8),
            static_cast<std::uint8_t>(pixel)};
  }

 private:
  static cairo_status_t readChunk(void* closure, unsigned char* data, unsigned int length) {
    Image* self = static_cast<Image*>(closure);
    if (self->read_ + length > self->png_.size()) return CAIRO_STATUS_READ_ERROR;
    std::memcpy(data, self->png_.data() + self->read_, length);
    self->read_ += length;
    return CAIRO_STATUS_SUCCESS;
  }

  std::string png_;
  size_t read_ = 0;
  cairo_surface_t* surface_ = nullptr;
};

ChartSeries horizontal(const std::string& name, double y, double x_low, double x_high) {
  ChartSeries series;
  series.name = name;
  series.points = {{x_low, y}, {(x_low + x_high) / 2, y}, {x_high, y}};
  return series;
}

// Three horizontal lines at y = 1, 2.5 and 4 over x = 0..10, legend outside the plot.
LineChart threeLevels() {
  LineChart chart;
  chart.title = "three levels";
  chart.x_label = "x";
  chart.y_label = "y";
  chart.series = {horizontal("low", 1, 0, 10), horizontal("middle", 2.5, 0, 10),
                  horizontal("high", 4, 0, 10)};
  chart.legend = LegendPlacement::OutsideRight;
  return chart;
}

TEST(LineChart, ImageHasTheRequestedSize) {
  for (const auto& [width, height] : {std::pair{640, 400}, std::pair{333, 777}}) {
    const Image image(chartPngBytes(threeLevels(), width, height));
    EXPECT_EQ(image.width(), width);
    EXPECT_EQ(image.height(), height);
  }
}

TEST(LineChart, PlotAreaLiesInsideTheImage) {
  const ChartLayout layout = layoutChart(threeLevels(), kWidthPx, kHeightPx);
  EXPECT_GT(layout.plot_left_px, 0);
  EXPECT_GT(layout.plot_top_px, 0);
  EXPECT_LT(layout.plot_right_px, kWidthPx);
  EXPECT_LT(layout.plot_bottom_px, kHeightPx);
  // The axes cover the data (ticks widen the range) and map it inside the plot area.
  EXPECT_LE(layout.y_ticks.low, 1);
  EXPECT_GE(layout.y_ticks.high, 4);
  EXPECT_GE(layout.y_to_pixel.toPixel(1), layout.plot_top_px);
  EXPECT_LE(layout.y_to_pixel.toPixel(1), layout.plot_bottom_px);
}

// Each series' colour lies along the pixel row its y maps to, and not a little above or below it;
// the lowest y value is the lowest line in the image (rows are not flipped).
TEST(LineChart, HorizontalSeriesDrawItsColourOnTheExpectedRows) {
  const LineChart chart = threeLevels();
  const ChartLayout layout = layoutChart(chart, kWidthPx, kHeightPx);
  const Image image(chartPngBytes(chart, kWidthPx, kHeightPx));
  for (int s = 0; s < 3; ++s) {
    const double y = chart.series[s].points[0].y;
    const double row = layout.y_to_pixel.toPixel(y);
    const Colour colour = paletteColour(s);
    for (const double x : {1.3, 3.7, 6.1, 8.9}) {  // between the grid lines at 0, 2, 4, ...
      const double column = layout.x_to_pixel.toPixel(x);
      EXPECT_EQ(image.at(column, row), colour) << "series " << s << " at x = " << x;
      EXPECT_NE(image.at(column, row - kClearOfLinePx), colour) << "series " << s << " above";
      EXPECT_NE(image.at(column, row + kClearOfLinePx), colour) << "series " << s << " below";
    }
  }
  EXPECT_GT(layout.y_to_pixel.toPixel(1), layout.y_to_pixel.toPixel(4));
}

TEST(LineChart, VerticalSeriesDrawsItsColourOnTheExpectedColumn) {
  LineChart chart = threeLevels();
  ChartSeries vertical;
  vertical.name = "vertical";
  vertical.points = {{7.3, 0.5}, {7.3, 4.5}};
  chart.series.push_back(vertical);
  const ChartLayout layout = layoutChart(chart, kWidthPx, kHeightPx);
  const Image image(chartPngBytes(chart, kWidthPx, kHeightPx));
  const double column = layout.x_to_pixel.toPixel(7.3);
  for (const double y : {0.7, 1.7, 3.3}) {  // clear of the horizontal lines and the grid
    const double row = layout.y_to_pixel.toPixel(y);
    EXPECT_EQ(image.at(column, row), paletteColour(3)) << "at y = " << y;
    EXPECT_NE(image.at(column - kClearOfLinePx, row), paletteColour(3));
  }
}

// On log-log axes a flat series at y = 100 runs along the row of 100, and the decades of the x
// axis are evenly spaced in pixels.
TEST(LineChart, LogAxesPlaceDecadesEvenly) {
  LineChart chart;
  chart.title = "log-log";
  chart.x_scale = AxisScale::Log;
  chart.y_scale = AxisScale::Log;
  chart.series = {horizontal("flat", 100, 1e-3, 1e2), horizontal("floor", 1e-2, 1e-3, 1e2)};
  chart.series[0].points = {{1e-3, 100}, {0.37, 100}, {1e2, 100}};
  const ChartLayout layout = layoutChart(chart, kWidthPx, kHeightPx);
  ASSERT_EQ(layout.x_ticks.major.size(), 6u);  // 1e-3 .. 1e2
  const double first_px = layout.x_to_pixel.toPixel(1e-3);
  const double decade_px = (layout.x_to_pixel.toPixel(1e2) - first_px) / 5;
  EXPECT_GT(decade_px, 50);  // a real spacing, not a collapsed axis
  for (size_t i = 0; i < layout.x_ticks.major.size(); ++i) {
    EXPECT_NEAR(layout.x_to_pixel.toPixel(layout.x_ticks.major[i]), first_px + i * decade_px, 1e-9);
  }
  const Image image(chartPngBytes(chart, kWidthPx, kHeightPx));
  const double row = layout.y_to_pixel.toPixel(100);
  for (const double x : {2.5e-3, 0.05, 3.0}) {  // between the decade grid lines
    EXPECT_EQ(image.at(layout.x_to_pixel.toPixel(x), row), paletteColour(0)) << "x = " << x;
  }
  EXPECT_EQ(image.at(layout.x_to_pixel.toPixel(0.05), layout.y_to_pixel.toPixel(1e-2)),
            paletteColour(1));
}

TEST(LineChart, MarkersAreDrawnAtTheirPoints) {
  LineChart chart = threeLevels();
  ChartSeries dots;
  dots.name = "dots";
  dots.style = SeriesStyle::Markers;
  dots.points = {{3.3, 1.8}, {5.7, 3.1}};
  chart.series.push_back(dots);
  const ChartLayout layout = layoutChart(chart, kWidthPx, kHeightPx);
  const Image image(chartPngBytes(chart, kWidthPx, kHeightPx));
  for (const ChartPoint& p : dots.points) {
    const double column = layout.x_to_pixel.toPixel(p.x);
    const double row = layout.y_to_pixel.toPixel(p.y);
    EXPECT_EQ(image.at(column, row), paletteColour(3));
  }
  // No line joins the markers: half-way between them is background.
  const double mid_column = layout.x_to_pixel.toPixel(4.5);
  const double mid_row = layout.y_to_pixel.toPixel(2.45);
  EXPECT_NE(image.at(mid_column, mid_row), paletteColour(3));
}

TEST(LineChart, SameInputGivesTheSameBytes) {
  const std::string first = chartPngBytes(threeLevels(), kWidthPx, kHeightPx);
  EXPECT_EQ(chartPngBytes(threeLevels(), kWidthPx, kHeightPx), first);
  // ...and the bytes depend on the data (a check that the comparison above can fail).
  LineChart moved = threeLevels();
  moved.series[1].points[1].y = 2.6;
  EXPECT_NE(chartPngBytes(moved, kWidthPx, kHeightPx), first);
  // The file holds exactly these bytes.
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / "line_chart_test_same.png";
  writeChartPng(threeLevels(), path.string(), kWidthPx, kHeightPx);
  std::ifstream in(path, std::ios::binary);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(written, first);
  std::filesystem::remove(path);
}

TEST(LineChart, BadSizesAreRejected) {
  const LineChart chart = threeLevels();
  expectValueRejected([&] { layoutChart(chart, 10, kHeightPx); }, "chart width (px) = 10");
  expectValueRejected([&] { layoutChart(chart, kWidthPx, 9000); }, "chart height (px) = 9000");
  expectValueRejected([&] { chartPngBytes(chart, -1, kHeightPx); }, "chart width (px) = -1");
}

TEST(LineChart, BadSeriesAreRejectedNamingSeriesAndPoint) {
  LineChart chart = threeLevels();
  chart.series.clear();
  expectRejected([&] { layoutChart(chart, kWidthPx, kHeightPx); },
                 {"chart 'three levels' has no series"});

  chart = threeLevels();
  chart.series[1].points.clear();
  expectRejected([&] { layoutChart(chart, kWidthPx, kHeightPx); },
                 {"series 'middle' has no points"});

  chart = threeLevels();
  chart.series[1].points[2].y = std::nan("");
  expectRejected([&] { layoutChart(chart, kWidthPx, kHeightPx); },
                 {"series 'middle' point 2", "y = nan", "finite"});
  chart = threeLevels();
  chart.series[0].points[0].x = -INFINITY;
  expectRejected([&] { layoutChart(chart, kWidthPx, kHeightPx); },
                 {"series 'low' point 0", "x = -inf"});

  chart = threeLevels();
  chart.y_scale = AxisScale::Log;
  chart.series[2].points[1].y = 0;
  expectRejected([&] { layoutChart(chart, kWidthPx, kHeightPx); },
                 {"series 'high' point 1", "y = 0", "logarithmic", "> 0"});
  chart = threeLevels();
  chart.x_scale = AxisScale::Log;  // x runs from 0
  expectRejected([&] { layoutChart(chart, kWidthPx, kHeightPx); },
                 {"series 'low' point 0", "x = 0", "logarithmic"});

  chart = threeLevels();
  chart.series[0].point_labels = {"only one"};
  expectRejected([&] { layoutChart(chart, kWidthPx, kHeightPx); },
                 {"series 'low' has 1 point labels for 3 points"});
}

TEST(LineChart, RejectedChartLeavesNoFile) {
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / "line_chart_test_rejected.png";
  std::filesystem::remove(path);
  LineChart chart = threeLevels();
  chart.series[0].points[1].x = std::nan("");
  EXPECT_THROW(writeChartPng(chart, path.string(), kWidthPx, kHeightPx), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
}

TEST(LineChart, UnwritablePathFailsWithItsName) {
  const std::string path = "/nonexistent-directory/chart.png";
  try {
    writeChartPng(threeLevels(), path, kWidthPx, kHeightPx);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr(path));
  }
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(LineChart, PaletteColoursDiffer) {
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < i; ++j) EXPECT_NE(paletteColour(i), paletteColour(j)) << i << ", " << j;
  }
  EXPECT_EQ(paletteColour(7), paletteColour(0));  // the palette repeats
  expectValueRejected([] { paletteColour(-1); }, "series index = -1");
}

}  // namespace
}  // namespace baize::render
