// Draws a Picture (render/draw_items.h) with OpenGL 3.3 core through any GlContext: everything is
// drawn into the renderer's own multisampled framebuffer (polygon and line edges antialiased by
// multisampling; discs and balls by an analytic edge in the fragment shader), resolved into a
// plain one that can be read back (PNG) or copied to a window (baize-view).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "render/camera.h"
#include "render/draw_items.h"
#include "render/gl_context.h"
#include "render/gl_functions.h"
#include "render/glyph_atlas.h"

namespace baize::render {

// An 8-bit RGBA image, top row first.
struct Image {
  int width_px = 0;
  int height_px = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, row by row from the top

  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (static_cast<std::size_t>(y) * width_px + x) * 4;
  }
};

// Samples per pixel asked for (fewer when the context offers fewer).
constexpr int kWantedSamples = 8;

// The legend's text height: the image height over this, within the limits below (px).
constexpr int kLegendLinesPerImage = 40;
constexpr int kMinLegendTextSize_px = 11;
constexpr int kMaxLegendTextSize_px = 40;
constexpr int kLegendMargin_px = 10;  // from the image's corner to the legend's panel

// The legend's text size for an image of this height, px.
int legendTextSize(int image_height_px);

class GlRenderer {
 public:
  // The context must be current on this thread for the renderer's whole life.
  // Throws std::runtime_error when a function is missing or the shaders do not build.
  explicit GlRenderer(const GlContext& context);
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  // Draws the picture as the camera sees it, at the camera's image size.
  void draw(const Picture& picture, const Camera& camera);
  // The last drawing, top row first (waits for the GL to finish).
  Image readImage();
  // Copies the last drawing into a framebuffer of the same size (0: a window's back buffer).
  void copyTo(unsigned framebuffer);

  std::string glVersion() const;  // GL_VERSION and GL_RENDERER, for messages
  int samples() const { return samples_; }

 private:
  void resize(int width_px, int height_px);
  void releaseFramebuffers();
  void drawLegend(const Picture& picture, const Camera& camera);
  // Makes `atlas` a font of this size (reusing it when it is one) and binds its texture.
  void useAtlas(std::unique_ptr<GlyphAtlas>& atlas, GLuint& texture, int size);
  void drawVertices(const void* vertices, std::size_t count, const float* view,
                    const float* projection);

  GlFunctions gl_;
  GLuint program_ = 0;
  GLint view_location_ = -1;
  GLint projection_location_ = -1;
  GLint atlas_location_ = -1;
  std::unique_ptr<GlyphAtlas> atlas_;  // made at the first legend, remade when its size changes
  GLuint atlas_texture_ = 0;
  std::unique_ptr<GlyphAtlas> label_atlas_;  // numbers on balls, sized to the balls as drawn
  GLuint label_texture_ = 0;
  GLuint vertex_array_ = 0;
  GLuint vertex_buffer_ = 0;
  GLuint multisample_framebuffer_ = 0, multisample_colour_ = 0;
  GLuint resolved_framebuffer_ = 0, resolved_colour_ = 0;
  int width_px_ = 0, height_px_ = 0;
  int samples_ = 1;
};

}  // namespace baize::render
