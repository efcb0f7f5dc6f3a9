#include "physics/value_text.h"

#include <charconv>
#include <stdexcept>

namespace baize::physics {

std::string valueText(double value) {
  // The shortest text that reads back as the same double: 0.3, 180 and 1e-06, not
  // 0.29999999999999999 and 9.9999999999999995e-07.
  char text[64];
  const std::to_chars_result end = std::to_chars(text, text + sizeof text, value);
  return std::string(text, end.ptr);
}

void rejectValue(const std::string& what, double value, const std::string& allowed) {
  throw std::invalid_argument(what + " = " + valueText(value) + " is not allowed: " + allowed);
}

}  // namespace baize::physics
