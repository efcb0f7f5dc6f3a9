// One axis of a line chart: which ticks to draw (1-2-5 steps on a linear axis, decades on a log
// axis), the range they span, and where a data value lands in pixels. Pure arithmetic with no
// drawing, so that tests can compute where a point must appear in the image.
#pragma once

#include <string>
#include <vector>

namespace baize::render {

enum class AxisScale { Linear, Log };

struct AxisTicks {
  AxisScale scale = AxisScale::Linear;
  // The axis runs from `low` to `high` (data units), both on a tick: the data range widened to the
  // next tick outside it, so that every point lies inside and both ends are labelled.
  double low = 0;
  double high = 1;
  std::vector<double> major;  // labelled ticks, increasing, first == low, last == high
  std::vector<double> minor;  // unlabelled ticks between them (log axes: 2..9 x each decade)
  // Linear axes: the step between major ticks, 1, 2 or 5 times a power of ten. Log axes: the step
  // between major ticks in decades (1, 2, 5, 10, ...).
  double step = 1;
  int step_exponent = 0;  // linear axes: step = 1, 2 or 5 x 10^step_exponent (sets label digits)
};

// Ticks for data in [data_low, data_high] on a linear axis, about `target_count` major ticks
// (2 to 100). The step is the smallest 1-2-5 step giving at most `target_count` intervals. A
// range of zero width (or of round-off width, below 1e-12 of the values) is widened to one unit of
// its value's decade each side (or [v - 1, v + 1] around zero). Throws std::invalid_argument for
// bounds that are not finite or exceed 1e300 in size, data_low > data_high, or a bad count.
AxisTicks linearTicks(double data_low, double data_high, int target_count);

// Ticks for data in [data_low, data_high] (both > 0) on a log axis: the range is widened to whole
// decades; major ticks every `step` decades with step from 1, 2, 5, 10, ... such that there are at
// most `target_count` intervals; minor ticks at 2..9 x 10^k when the step is one decade. Values
// must lie in [1e-300, 1e300].
AxisTicks logTicks(double data_low, double data_high, int target_count);

// The text under a major tick: "0.25", "-10", "1500" on linear axes (as many decimals as the step
// needs; "1.5e-06", "2e+07" for steps below 10^-4 or above 10^5); "10⁻⁶", "1", "10", "10³" (UTF-8
// superscripts) on log axes.
std::string tickLabel(const AxisTicks& ticks, double value);

// Data value -> pixel coordinate along one axis: `low` of the ticks maps to pixel_at_low and
// `high` to pixel_at_high (for a y axis pixel_at_low is the bottom, the larger pixel row).
// Log axes map log10 of the value linearly, so decades are evenly spaced.
class AxisMapping {
 public:
  AxisMapping(const AxisTicks& ticks, double pixel_at_low, double pixel_at_high);
  double toPixel(double value) const;

 private:
  AxisScale scale_;
  double position_low_;   // low, or log10(low) on a log axis
  double position_high_;  // likewise for high
  double pixel_at_low_;
  double pixel_at_high_;
};

}  // namespace baize::render
