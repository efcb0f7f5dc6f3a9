#include "render/glyph_atlas.h"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace baize::render {
namespace {

constexpr int kFirstCharacter = 32;
constexpr int kLastCharacter = 126;
// Empty pixels between glyphs in the atlas, so that sampling one never picks up its neighbour.
constexpr int kGlyphPadding_px = 1;
// The legend's font family (Debian: fonts-dejavu-core), located through fontconfig.
constexpr const char* kDefaultFontFamily = "DejaVu Sans";

}  // namespace

std::string defaultFontPath() {
  // Asked once: fontconfig's answer does not change while the program runs.
  static const std::string path = [] {
    FcConfig* config = FcInitLoadConfigAndFonts();
    if (config == nullptr) throw std::runtime_error("fontconfig cannot load its configuration");
    const std::unique_ptr<FcConfig, void (*)(FcConfig*)> config_owner(config, FcConfigDestroy);
    FcPattern* wanted = FcNameParse(reinterpret_cast<const FcChar8*>(kDefaultFontFamily));
    const std::unique_ptr<FcPattern, void (*)(FcPattern*)> wanted_owner(wanted, FcPatternDestroy);
    FcConfigSubstitute(config, wanted, FcMatchPattern);
    FcDefaultSubstitute(wanted);
    FcResult result = FcResultNoMatch;
    FcPattern* match = FcFontMatch(config, wanted, &result);
    if (match == nullptr) {
      throw std::runtime_error(std::string("fontconfig finds no font for '") + kDefaultFontFamily +
                               "' (Debian: install fonts-dejavu-core)");
    }
    const std::unique_ptr<FcPattern, void (*)(FcPattern*)> match_owner(match, FcPatternDestroy);
    FcChar8* file = nullptr;
    if (FcPatternGetString(match, FC_FILE, 0, &file) != FcResultMatch || file == nullptr) {
      throw std::runtime_error(std::string("fontconfig's match for '") + kDefaultFontFamily +
                               "' names no file");
    }
    return std::string(reinterpret_cast<const char*>(file));
  }();
  return path;
}

GlyphAtlas::GlyphAtlas(const std::string& font_path, int pixel_size) : pixel_size_(pixel_size) {
  if (pixel_size < kMinAtlasTextSize_px || pixel_size > kMaxAtlasTextSize_px) {
    throw std::invalid_argument("text size " + std::to_string(pixel_size) +
                                " px is not allowed: it must lie in [6, 200]");
  }
  FT_Library library = nullptr;
  if (FT_Init_FreeType(&library) != 0) throw std::runtime_error("FreeType cannot start");
  const std::unique_ptr<FT_LibraryRec_, FT_Error (*)(FT_Library)> library_owner(library,
                                                                                FT_Done_FreeType);
  FT_Face face = nullptr;
  if (FT_New_Face(library, font_path.c_str(), 0, &face) != 0) {
    throw std::runtime_error("cannot load the font '" + font_path +
                             "' (Debian: install fonts-dejavu-core)");
  }
  const std::unique_ptr<FT_FaceRec_, FT_Error (*)(FT_Face)> face_owner(face, FT_Done_Face);
  if (FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(pixel_size)) != 0) {
    throw std::runtime_error("the font '" + font_path + "' has no size " +
                             std::to_string(pixel_size) + " px");
  }
  ascender_ = static_cast<int>(face->size->metrics.ascender >> 6);
  line_height_ = static_cast<int>(face->size->metrics.height >> 6);

  // Rasterise each glyph once into its own bitmap, then pack them in rows of a fixed-width atlas.
  struct Bitmap {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;
  };
  std::array<Bitmap, 95> bitmaps;
  for (int c = kFirstCharacter; c <= kLastCharacter; ++c) {
    if (FT_Load_Char(face, static_cast<FT_ULong>(c), FT_LOAD_RENDER) != 0) {
      throw std::runtime_error("the font '" + font_path + "' cannot draw '" +
                               std::string(1, static_cast<char>(c)) + "'");
    }
    const FT_GlyphSlot slot = face->glyph;
    Glyph& g = glyphs_[c - kFirstCharacter];
    Bitmap& b = bitmaps[c - kFirstCharacter];
    g.width = b.width = static_cast<int>(slot->bitmap.width);
    g.height = b.height = static_cast<int>(slot->bitmap.rows);
    g.bearing_x = slot->bitmap_left;
    g.bearing_y = slot->bitmap_top;
    g.advance = static_cast<int>(slot->advance.x >> 6);
    b.pixels.resize(static_cast<std::size_t>(b.width) * b.height);
    for (int y = 0; y < b.height; ++y) {
      std::copy_n(slot->bitmap.buffer + y * slot->bitmap.pitch, b.width,
                  b.pixels.data() + static_cast<std::size_t>(y) * b.width);
    }
  }
  width_ = 16 * (pixel_size + 2 * kGlyphPadding_px);
  int pen_x = kGlyphPadding_px, pen_y = kGlyphPadding_px, row_height = 0;
  for (std::size_t i = 0; i < glyphs_.size(); ++i) {
    if (pen_x + glyphs_[i].width + kGlyphPadding_px > width_) {
      pen_x = kGlyphPadding_px;
      pen_y += row_height + kGlyphPadding_px;
      row_height = 0;
    }
    glyphs_[i].x = pen_x;
    glyphs_[i].y = pen_y;
    pen_x += glyphs_[i].width + kGlyphPadding_px;
    row_height = std::max(row_height, glyphs_[i].height);
  }
  height_ = pen_y + row_height + kGlyphPadding_px;
  coverage_.assign(static_cast<std::size_t>(width_) * height_, 0);
  for (std::size_t i = 0; i < glyphs_.size(); ++i) {
    const Glyph& g = glyphs_[i];
    for (int y = 0; y < g.height; ++y) {
      std::copy_n(bitmaps[i].pixels.data() + static_cast<std::size_t>(y) * g.width, g.width,
                  coverage_.data() + static_cast<std::size_t>(g.y + y) * width_ + g.x);
    }
  }
}

const Glyph& GlyphAtlas::glyph(char c) const {
  const int code = static_cast<unsigned char>(c);
  if (code < kFirstCharacter || code > kLastCharacter) return glyphs_['?' - kFirstCharacter];
  return glyphs_[code - kFirstCharacter];
}

int GlyphAtlas::textWidth(const std::string& text) const {
  int width = 0;
  for (char c : text) width += glyph(c).advance;
  return width;
}

}  // namespace baize::render
