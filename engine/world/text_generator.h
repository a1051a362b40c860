// Letters and numbers spelled in voxels with the built-in 5x7 font (core/bitmap_font.h): the
// thesis's emissive letters scene sets letters into walls and numbers into the floor. A glyph
// is written into the surface layer it sits on, `depth` voxels deep, so a letter set into a
// wall is enclosed on every side but its face.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "world/brick_grid.h"

namespace engine::world {

struct TextParams {
    std::string text;
    // Lower-left corner of the first glyph, in the surface layer; `right` runs along the line,
    // `up` from the baseline to the top of the glyphs (both axis-aligned unit vectors). The face
    // looks towards cross(right, up); depth layers go the other way, into the surface.
    glm::ivec3 origin{0};
    glm::ivec3 right{1, 0, 0};
    glm::ivec3 up{0, 1, 0};
    int scale = 1;    // voxels per font pixel along right and up
    int depth = 1;    // layers into the surface
    int spacing = 1;  // font pixels between glyphs
    MaterialId material = kEmpty;
};

// Checks right/up are perpendicular axis unit vectors, scale/depth/spacing are positive and
// every character has a glyph; returns an empty string when fine, else the problem.
std::string validateTextParams(const TextParams& p);
// Voxels the text sets (before clipping to the world): set font pixels x scale^2 x depth.
int textVoxelCount(const TextParams& p);
// Advance of one glyph along `right`, in voxels.
inline int textGlyphAdvance(const TextParams& p) { return (5 + p.spacing) * p.scale; }
void generateText(BrickGrid& grid, const TextParams& p);

}  // namespace engine::world
