#include "physics/value_text.h"

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

}  // namespace baize::physics
