// Error messages that name a bad value: the value printed so that it reads back exactly.
#pragma once

#include <string>

namespace baize::physics {

// `value` with 17 significant digits ("nan", "inf" as such).
std::string valueText(double value);

// Throws std::invalid_argument("<what> = <value> is not allowed: <allowed>").
[[noreturn]] void rejectValue(const std::string& what, double value, const std::string& allowed);

// Rejects `value` unless it is finite.
void requireFinite(const std::string& what, double value);

}  // namespace baize::physics
