#include "render/chart_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "physics/value_text.h"

namespace baize::render {
namespace {

// Quotients such as 0.3 / 0.1 come out as 2.9999999999999996; a data bound within this fraction
// of a step from a tick counts as on the tick, so the axis is not widened by a whole step for
// round-off. Dimensionless (fraction of one step).
constexpr double kOnTickFraction = 1e-9;

// Ticks are computed with powers of ten, which overflow past 1e308: values beyond this are
// refused rather than drawn wrongly.
constexpr double kLargestAxisMagnitude = 1e300;
// A linear range narrower than this fraction of its values' size is round-off (a quantity that is
// constant up to its last bits) and is drawn as the one value it is. Dimensionless.
constexpr double kFlatRangeFraction = 1e-12;
// Below this a linear step's power of ten would underflow. Same unit as the data.
constexpr double kSmallestStep = 1e-290;
// More ticks than this cannot be labelled on any image the charts allow (8192 px).
constexpr int kMaxTargetCount = 100;
// Linear labels use plain decimals for steps of 10^-4 to 10^5 and exponent notation outside, so
// that no label runs to twenty digits.
constexpr int kSmallestFixedExponent = -4;
constexpr int kLargestFixedExponent = 5;

// The 1-2-5 mantissas of a linear step, in increasing order.
constexpr int kStepMantissas[] = {1, 2, 5};

// The steps of a log axis, in decades, before they repeat times ten.
constexpr int kDecadeStepMantissas[] = {1, 2, 5};

void requireTargetCount(int target_count) {
  if (target_count < 2 || target_count > kMaxTargetCount) {
    physics::rejectValue("axis tick count", target_count,
                         "it must lie in [2, " + std::to_string(kMaxTargetCount) + "]");
  }
}

void requireChartable(const char* what, double value) {
  physics::requireFinite(what, value);
  if (std::fabs(value) > kLargestAxisMagnitude) {
    physics::rejectValue(what, value,
                         "its size must be at most " + physics::valueText(kLargestAxisMagnitude));
  }
}

// i * mantissa * 10^exponent, computed so that a tick such as 3 x 0.1 is the double nearest 0.3
// (dividing by an exact power of ten rounds once; multiplying by 0.1 rounds twice).
double tickValue(long long i, int mantissa, int exponent) {
  const double count = static_cast<double>(i) * mantissa;
  if (exponent >= 0) return count * std::pow(10.0, exponent);
  return count / std::pow(10.0, -exponent);
}

const char* superscriptDigit(int digit) {
  static const char* const kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  return kDigits[digit];
}

}  // namespace

AxisTicks linearTicks(double data_low, double data_high, int target_count) {
  requireChartable("axis low end", data_low);
  requireChartable("axis high end", data_high);
  if (data_low > data_high) {
    physics::rejectValue("axis low end", data_low,
                         "it must be <= the high end " + physics::valueText(data_high));
  }
  requireTargetCount(target_count);
  const double size = std::max(std::fabs(data_low), std::fabs(data_high));
  if (data_high - data_low <= kFlatRangeFraction * size ||
      data_high - data_low < kSmallestStep * target_count) {
    // One value: an axis one unit of its own decade wide each side, so the value sits mid-axis.
    const double value = data_low + (data_high - data_low) / 2;
    const double pad = std::fabs(value) < kSmallestStep
                           ? 1.0
                           : std::pow(10.0, std::floor(std::log10(std::fabs(value))));
    data_low = value - pad;
    data_high = value + pad;
  }
  const double raw_step = (data_high - data_low) / target_count;
  int exponent = static_cast<int>(std::floor(std::log10(raw_step)));
  // Widening to whole steps can add up to two intervals, so larger steps are tried until it fits.
  for (;; ++exponent) {
    for (const int mantissa : kStepMantissas) {
      const double step = tickValue(1, mantissa, exponent);
      const long long first = static_cast<long long>(std::floor(data_low / step + kOnTickFraction));
      const long long last = static_cast<long long>(std::ceil(data_high / step - kOnTickFraction));
      if (last - first > target_count) continue;
      AxisTicks ticks;
      ticks.scale = AxisScale::Linear;
      ticks.step = step;
      ticks.step_exponent = exponent;
      for (long long i = first; i <= last; ++i) {
        ticks.major.push_back(tickValue(i, mantissa, exponent));
      }
      ticks.low = ticks.major.front();
      ticks.high = ticks.major.back();
      return ticks;
    }
  }
}

AxisTicks logTicks(double data_low, double data_high, int target_count) {
  requireChartable("log axis low end", data_low);
  requireChartable("log axis high end", data_high);
  if (!(data_low > 0)) {
    physics::rejectValue("log axis low end", data_low, "a logarithmic axis needs values > 0");
  }
  if (data_low < 1 / kLargestAxisMagnitude) {
    physics::rejectValue("log axis low end", data_low,
                         "it must be at least " + physics::valueText(1 / kLargestAxisMagnitude));
  }
  if (data_low > data_high) {
    physics::rejectValue("log axis low end", data_low,
                         "it must be <= the high end " + physics::valueText(data_high));
  }
  requireTargetCount(target_count);
  const long long low_decade =
      static_cast<long long>(std::floor(std::log10(data_low) + kOnTickFraction));
  long long high_decade =
      static_cast<long long>(std::ceil(std::log10(data_high) - kOnTickFraction));
  if (high_decade == low_decade) ++high_decade;  // at least one whole decade
  for (long long scale = 1;; scale *= 10) {
    for (const int mantissa : kDecadeStepMantissas) {
      const long long step = mantissa * scale;
      // Floor and ceiling division for negative decades too.
      const long long first = (low_decade >= 0 ? low_decade : low_decade - step + 1) / step;
      const long long last = (high_decade >= 0 ? high_decade + step - 1 : high_decade) / step;
      if (last - first > target_count) continue;
      AxisTicks ticks;
      ticks.scale = AxisScale::Log;
      ticks.step = static_cast<double>(step);
      for (long long i = first; i <= last; ++i) {
        ticks.major.push_back(std::pow(10.0, static_cast<double>(i * step)));
      }
      if (step == 1) {
        for (long long decade = first; decade < last; ++decade) {
          const double base = std::pow(10.0, static_cast<double>(decade));
          for (int m = 2; m <= 9; ++m) ticks.minor.push_back(m * base);
        }
      }
      ticks.low = ticks.major.front();
      ticks.high = ticks.major.back();
      return ticks;
    }
  }
}

std::string tickLabel(const AxisTicks& ticks, double value) {
  if (ticks.scale == AxisScale::Log) {
    const long long decade = std::llround(std::log10(value));
    if (decade == 0) return "1";
    if (decade == 1) return "10";
    std::string label = "10";
    if (decade < 0) label += "⁻";
    const std::string digits = std::to_string(decade < 0 ? -decade : decade);
    for (const char digit : digits) label += superscriptDigit(digit - '0');
    return label;
  }
  char text[64];
  const int exponent = ticks.step_exponent;
  if (value != 0 && (exponent < kSmallestFixedExponent || exponent > kLargestFixedExponent)) {
    // As many significant digits as lie between the value's leading digit and the step's.
    const int leading = static_cast<int>(std::floor(std::log10(std::fabs(value)) + 1e-9));
    std::snprintf(text, sizeof text, "%.*e", std::max(0, leading - exponent), value);
    return text;
  }
  std::snprintf(text, sizeof text, "%.*f", exponent < 0 ? -exponent : 0, value);
  std::string label = text;
  // A tick at -1e-17 prints as "-0.0": zero has no sign.
  if (label.find_first_not_of("-0.") == std::string::npos && label[0] == '-') label.erase(0, 1);
  return label;
}

AxisMapping::AxisMapping(const AxisTicks& ticks, double pixel_at_low, double pixel_at_high)
    : scale_(ticks.scale),
      position_low_(ticks.scale == AxisScale::Log ? std::log10(ticks.low) : ticks.low),
      position_high_(ticks.scale == AxisScale::Log ? std::log10(ticks.high) : ticks.high),
      pixel_at_low_(pixel_at_low),
      pixel_at_high_(pixel_at_high) {}

double AxisMapping::toPixel(double value) const {
  const double position = scale_ == AxisScale::Log ? std::log10(value) : value;
  const double fraction = (position - position_low_) / (position_high_ - position_low_);
  return pixel_at_low_ + fraction * (pixel_at_high_ - pixel_at_low_);
}

}  // namespace baize::render
