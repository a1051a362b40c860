#include "world/text_generator.h"

#include <cstdlib>
#include <fmt/format.h>

#include "core/bitmap_font.h"
#include "world/world_edits.h"

namespace engine::world {

namespace {

bool axisUnit(glm::ivec3 v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z) == 1; }

}  // namespace

std::string validateTextParams(const TextParams& p) {
    if (!axisUnit(p.right) || !axisUnit(p.up) ||
        glm::dot(glm::vec3(p.right), glm::vec3(p.up)) != 0.0f)
        return "'right' and 'up' must be perpendicular axis directions such as [1, 0, 0] and [0, "
               "1, 0]";
    if (p.scale < 1 || p.scale > 64) return "'scale' must be in 1..64";
    if (p.depth < 1 || p.depth > 64) return "'depth' must be in 1..64";
    if (p.spacing < 0 || p.spacing > 64) return "'spacing' must be in 0..64";
    if (char c = firstMissingGlyph(p.text))
        return fmt::format("no glyph for '{}' (the font has A-Z, 0-9, . - + :)", c);
    return {};
}

int textVoxelCount(const TextParams& p) {
    int pixels = 0;
    for (char c : p.text) pixels += glyphPixelCount(c);
    return pixels * p.scale * p.scale * p.depth;
}

void generateText(BrickGrid& grid, const TextParams& p) {
    const glm::ivec3 inward = -glm::ivec3(glm::cross(glm::vec3(p.right), glm::vec3(p.up)));
    for (std::size_t i = 0; i < p.text.size(); ++i) {
        glm::ivec3 glyphOrigin = p.origin + p.right * (int(i) * textGlyphAdvance(p));
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int gx = 0; gx < kGlyphWidth; ++gx) {
                if (!glyphPixel(p.text[i], gx, row)) continue;
                // Row 0 is the glyph's top: it sits (kGlyphHeight - 1) pixels above the baseline.
                glm::ivec3 corner = glyphOrigin + p.right * (gx * p.scale) +
                                    p.up * ((kGlyphHeight - 1 - row) * p.scale);
                glm::ivec3 far = corner + (p.right + p.up) * (p.scale - 1) + inward * (p.depth - 1);
                fillBox(grid, Box{glm::min(corner, far), glm::max(corner, far) + 1}, p.material);
            }
    }
}

}  // namespace engine::world
