#include "core/bitmap_font.h"

#include <gtest/gtest.h>
#include <set>
#include <string>

using namespace engine;

namespace {

std::string bitmap(char c) {
    std::string s;
    for (int row = 0; row < kGlyphHeight; ++row)
        for (int x = 0; x < kGlyphWidth; ++x) s += glyphPixel(c, x, row) ? '#' : '.';
    return s;
}

}  // namespace

TEST(BitmapFont, HasEveryLetterAndDigitAndTheyDiffer) {
    std::set<std::string> seen;
    for (char c : std::string("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.-+:")) {
        ASSERT_TRUE(hasGlyph(c)) << c;
        EXPECT_GT(glyphPixelCount(c), 0) << c;
        EXPECT_TRUE(seen.insert(bitmap(c)).second) << "'" << c << "' looks like another glyph";
    }
    EXPECT_TRUE(hasGlyph(' '));
    EXPECT_EQ(glyphPixelCount(' '), 0);
}

TEST(BitmapFont, LowerCaseUsesUpperCaseAndMissingGlyphsAreReported) {
    EXPECT_EQ(bitmap('q'), bitmap('Q'));
    EXPECT_FALSE(hasGlyph('%'));
    EXPECT_FALSE(glyphPixel('%', 0, 0));
    EXPECT_EQ(glyphPixelCount('%'), 0);
    EXPECT_EQ(firstMissingGlyph("VOXEL 42"), '\0');
    EXPECT_EQ(firstMissingGlyph("50% OFF"), '%');
}

TEST(BitmapFont, PixelsAreReadTopRowFirst) {
    // L: a vertical bar on the left and a full bottom row.
    for (int row = 0; row < kGlyphHeight; ++row) EXPECT_TRUE(glyphPixel('L', 0, row)) << row;
    for (int x = 0; x < kGlyphWidth; ++x) EXPECT_TRUE(glyphPixel('L', x, kGlyphHeight - 1)) << x;
    EXPECT_FALSE(glyphPixel('L', 4, 0));
    EXPECT_FALSE(glyphPixel('L', -1, 0));
    EXPECT_FALSE(glyphPixel('L', 0, kGlyphHeight));
    EXPECT_EQ(glyphPixelCount('L'), 11);
}
