// Text for numbers in machine-readable output (CSV, error messages): every double with 17
// significant digits, so that reading the text back gives the same double bit for bit.
#pragma once

#include <string>

namespace baize::tools {

std::string fullPrecision(double value);

}  // namespace baize::tools
