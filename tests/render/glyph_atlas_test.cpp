#include "render/glyph_atlas.h"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>

namespace baize::render {
namespace {

int coverageOf(const GlyphAtlas& atlas, const Glyph& g) {
  int sum = 0;
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) sum += atlas.coverage()[(g.y + y) * atlas.width() + g.x + x];
  }
  return sum;
}

TEST(GlyphAtlas, GlyphsHaveInkSpacesHaveNoneAndWidthsAddUp) {
  const GlyphAtlas atlas(defaultFontPath(), 20);
  EXPECT_EQ(atlas.coverage().size(), static_cast<std::size_t>(atlas.width()) * atlas.height());
  const Glyph& m = atlas.glyph('M');
  EXPECT_GT(m.width, 0);
  EXPECT_GT(m.height, 0);
  EXPECT_LE(m.height, atlas.lineHeight());
  EXPECT_GT(coverageOf(atlas, m), 0);
  const Glyph& space = atlas.glyph(' ');
  EXPECT_EQ(coverageOf(atlas, space), 0);
  EXPECT_GT(space.advance, 0);
  EXPECT_EQ(atlas.textWidth("MM "), 2 * m.advance + space.advance);
  EXPECT_GT(atlas.textWidth("MMM"), atlas.textWidth("iii"));  // a proportional font
  // Outside printable ASCII: drawn as '?'.
  EXPECT_EQ(&atlas.glyph('\n'), &atlas.glyph('?'));
}

TEST(GlyphAtlas, GlyphsDoNotOverlapInTheAtlas) {
  const GlyphAtlas atlas(defaultFontPath(), 17);
  std::vector<int> owner(atlas.coverage().size(), -1);
  for (int c = 32; c <= 126; ++c) {
    const Glyph& g = atlas.glyph(static_cast<char>(c));
    ASSERT_LE(g.x + g.width, atlas.width());
    ASSERT_LE(g.y + g.height, atlas.height());
    for (int y = 0; y < g.height; ++y) {
      for (int x = 0; x < g.width; ++x) {
        int& o = owner[(g.y + y) * atlas.width() + g.x + x];
        EXPECT_EQ(o, -1) << "'" << static_cast<char>(c) << "' overlaps '" << static_cast<char>(o)
                         << "'";
        o = c;
      }
    }
  }
}

TEST(GlyphAtlas, LargerTextHasLargerGlyphs) {
  const GlyphAtlas small(defaultFontPath(), 12), large(defaultFontPath(), 36);
  EXPECT_GT(large.glyph('H').height, 2 * small.glyph('H').height);
  EXPECT_GT(large.textWidth("Baize"), 2 * small.textWidth("Baize"));
}

TEST(GlyphAtlas, MissingFontAndBadSizesAreRefused) {
  EXPECT_THROW(GlyphAtlas("/no/such/font.ttf", 20), std::runtime_error);
  EXPECT_THROW(GlyphAtlas(defaultFontPath(), 0), std::invalid_argument);
  EXPECT_THROW(GlyphAtlas(defaultFontPath(), 1000), std::invalid_argument);
}

}  // namespace
}  // namespace baize::render
