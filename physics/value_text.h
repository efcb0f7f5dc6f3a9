// Error messages that name a bad value: the value printed so that it reads back exactly.
#pragma once

#include <cmath>
#include <string>

namespace baize::physics {

// `value` with 17 significant digits ("nan", "inf" as such).
std::string valueText(double value);

// Throws std::invalid_argument("<what> = <value> is not allowed: <allowed>").
[[noreturn]] void rejectValue(const std::string& what, double value, const std::string& allowed);

// Rejects `value` unless it is finite. Checks before building any text: validation runs on hot
// paths.
inline void requireFinite(const char* what, double value) {
  if (!std::isfinite(value)) rejectValue(what, value, "it must be a finite number");
}

}  // namespace baize::physics
