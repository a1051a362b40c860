// A tiny 5x7 bitmap font (A-Z, 0-9, space and . - + :), drawn by hand for this engine. It
// spells letters and numbers into worlds (world/text_generator.h) and labels image legends
// (metrics/heat_map.h); both want exact, resolution-free pixels rather than a rasteriser.
#pragma once

#include <string_view>

namespace engine {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;

// Lower-case letters use the upper-case glyphs.
bool hasGlyph(char c);
// Whether pixel (x, row) of the glyph is set; row 0 is the top. False for missing glyphs and
// pixels outside 0..4 x 0..6.
bool glyphPixel(char c, int x, int row);
// Set pixels of a glyph (0 for space and missing glyphs).
int glyphPixelCount(char c);
// The first character of `text` without a glyph, or '\0' when all have one.
char firstMissingGlyph(std::string_view text);

}  // namespace engine
