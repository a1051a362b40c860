// A mountain landscape (the thesis's mountain scene, §3.2): one massif rising from rolling
// foothills, ridged noise carving ridges and gullies into its flanks, optional terraces that
// give the slopes voxel steps and corners, snow above a line and bare rock on steep steps.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "world/brick_grid.h"
#include "world/height_field.h"

namespace engine::world {

struct MountainParams {
    ColumnMaterials materials;  // top, soil, rock, snow above snowLine, cliff on steep steps
    glm::vec2 peak{0.0f};       // (x, z) of the summit
    float peakHeight = 120.0f;  // summit height (before ridges)
    float baseHeight = 16.0f;   // the foothills' mean height
    float radius = 180.0f;      // the massif falls to the foothills at this distance
    float hills = 8.0f;         // amplitude of the foothills' rolling noise
    float ridges = 0.35f;       // 0..1: how deeply ridged noise cuts the flanks
    float wavelength = 64.0f;   // of the first ridge octave, in voxels
    int octaves = 4;
    int terrace = 0;  // > 0: heights snap down to multiples of this (steps)
    std::uint32_t seed = 1;
};

// The column height (first empty y) at (x, z), without looking at the grid.
int mountainHeight(const MountainParams& p, int x, int z);
void generateMountain(BrickGrid& grid, const MountainParams& p);

}  // namespace engine::world
