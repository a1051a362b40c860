// Many small, equal lights scattered over the ground (the thesis's mountain scene: 9 408
// emissive voxels): one light per cell of a regular grid over the footprint, at a seeded random
// spot inside its cell (stratified, so they spread evenly but do not line up), standing on the
// highest ground under it. Lights never overlap, so the emissive voxel count is exactly
// cells x size.x * size.y * size.z unless a light would poke out of the world's top.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "world/brick_grid.h"

namespace engine::world {

struct ScatteredLightsParams {
    int spacing = 8;           // grid cell edge in voxels
    glm::ivec3 size{1, 3, 1};  // each light's box; x and z at most spacing
    int margin = 0;            // keep this far from the world's x and z edges
    std::uint32_t seed = 9;
    MaterialId light = kEmpty;
};

// Returns the number of lights placed.
int generateScatteredLights(BrickGrid& grid, const ScatteredLightsParams& p);

}  // namespace engine::world
