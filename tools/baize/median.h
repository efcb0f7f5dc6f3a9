// The median the benchmarks report: robust to the slow outliers of a shared machine.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace baize::tools {

// The middle value; for an even count, the mean of the two middle ones. Throws on no values.
inline double median(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("median of no values");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

}  // namespace baize::tools
