// Shared by the render tests: one off-screen context per test program with the rasteriser pinned
// (llvmpipe), and colour comparisons on read-back pixels.
#pragma once

#include <cstdlib>
#include <memory>

#include "render/draw_items.h"
#include "render/gl_renderer.h"
#include "render/osmesa_context.h"

namespace baize::render {

// A pixel channel may differ from the colour drawn by this much (0-255): 8-bit rounding and the
// antialiasing of neighbouring edges; far below the gap between any two colours compared.
constexpr int kChannelTolerance = 3;

inline GlRenderer& testRenderer() {
  static std::unique_ptr<OsmesaContext> context;
  static std::unique_ptr<GlRenderer> renderer;
  if (!renderer) {
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    context = std::make_unique<OsmesaContext>();
    renderer = std::make_unique<GlRenderer>(*context);
  }
  return *renderer;
}

inline int channel(float value) { return static_cast<int>(value * 255.0f + 0.5f); }

// Largest channel difference between a pixel and a colour, 0-255.
inline int colourDistance(const std::uint8_t* pixel, const Rgba& colour) {
  const int d[3] = {std::abs(pixel[0] - channel(colour.r)), std::abs(pixel[1] - channel(colour.g)),
                    std::abs(pixel[2] - channel(colour.b))};
  return std::max(d[0], std::max(d[1], d[2]));
}

}  // namespace baize::render
