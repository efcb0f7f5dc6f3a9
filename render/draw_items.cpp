#include "render/draw_items.h"

#include <cctype>
#include <stdexcept>

namespace baize::render {

Rgba colourFromHex(const std::string& hex) {
  const auto digit = [&](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower >= 'a' && lower <= 'f') return lower - 'a' + 10;
    return -1;
  };
  bool valid = hex.size() == 7 && hex[0] == '#';
  for (std::size_t i = 1; valid && i < hex.size(); ++i) valid = digit(hex[i]) >= 0;
  if (!valid) {
    throw std::invalid_argument("colour '" + hex +
                                "' is not allowed: it must be \"#rrggbb\" with hexadecimal digits");
  }
  const auto channel = [&](int i) {
    return static_cast<float>(digit(hex[i]) * 16 + digit(hex[i + 1])) / 255.0f;
  };
  return Rgba{channel(1), channel(3), channel(5), 1.0f};
}

}  // namespace baize::render
