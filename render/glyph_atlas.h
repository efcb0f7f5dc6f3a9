// Text for legends: the printable ASCII glyphs of a TrueType font rasterised by FreeType into one
// 8-bit coverage image (an atlas) that the renderer uploads as a texture. No hand-made font
// rasterising; the default font is DejaVu Sans (Debian: fonts-dejavu-core).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace baize::render {

// Text sizes an atlas accepts, px.
constexpr int kMinAtlasTextSize_px = 6;
constexpr int kMaxAtlasTextSize_px = 200;

// The font used when none is given.
std::string defaultFontPath();

struct Glyph {
  int x = 0, y = 0;                  // top-left corner in the atlas, px
  int width = 0, height = 0;         // bitmap size, px
  int bearing_x = 0, bearing_y = 0;  // from the pen position to the bitmap's left and top edges
  int advance = 0;                   // pen movement after the glyph, px
};

class GlyphAtlas {
 public:
  // Rasterises characters 32-126 at this pixel size. Throws std::runtime_error naming the font
  // when FreeType cannot load it, std::invalid_argument for a size outside [6, 200] px.
  GlyphAtlas(const std::string& font_path, int pixel_size);

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<std::uint8_t>& coverage() const { return coverage_; }  // width * height
  int pixelSize() const { return pixel_size_; }
  int ascender() const { return ascender_; }       // baseline to the top of tall glyphs, px
  int lineHeight() const { return line_height_; }  // baseline to baseline, px

  // The glyph of a character; characters outside 32-126 are drawn as '?'.
  const Glyph& glyph(char c) const;
  // Sum of the advances of the text's characters, px.
  int textWidth(const std::string& text) const;

 private:
  int pixel_size_ = 0;
  int width_ = 0, height_ = 0;
  int ascender_ = 0, line_height_ = 0;
  std::vector<std::uint8_t> coverage_;
  std::array<Glyph, 95> glyphs_{};
};

}  // namespace baize::render
