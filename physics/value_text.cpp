#include "physics/value_text.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace baize::physics {

std::string valueText(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

void rejectValue(const std::string& what, double value, const std::string& allowed) {
  throw std::invalid_argument(what + " = " + valueText(value) + " is not allowed: " + allowed);
}

void requireFinite(const std::string& what, double value) {
  if (!std::isfinite(value)) rejectValue(what, value, "it must be a finite number");
}

}  // namespace baize::physics
