// Text for a double that reads back exactly: error messages naming a bad value, CSV output.
#pragma once

#include <cmath>
#include <string>

namespace baize::physics {

// The shortest text that reads back as the same double bit for bit ("nan", "inf" as such): 0.3,
// not 0.29999999999999999; also the number format of the tools' CSV output.
std::string valueText(double value);

// Throws std::invalid_argument("<what> = <value> is not allowed: <allowed>").
[[noreturn]] void rejectValue(const std::string& what, double value, const std::string& allowed);

// Rejects `value` unless it is finite. Checks before building any text: validation runs on hot
// paths.
inline void requireFinite(const char* what, double value) {
  if (!std::isfinite(value)) rejectValue(what, value, "it must be a finite number");
}

}  // namespace baize::physics
