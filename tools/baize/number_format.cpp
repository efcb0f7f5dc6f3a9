#include "tools/baize/number_format.h"

#include <limits>
#include <sstream>

namespace baize::tools {

std::string fullPrecision(double value) {
  std::ostringstream out;
  out.precision(std::numeric_limits<double>::max_digits10);  // 17 for IEEE doubles
  out << value;
  return out.str();
}

}  // namespace baize::tools
