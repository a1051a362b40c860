// A straight bridge deck with railings and a row of lights along each edge (the flying
// apartments scene joins two blocks with one): a deck, girders and cross beams underneath,
// railing posts with a top rail, and one light voxel on the deck beside the railing every
// `lightSpacing` voxels.
#pragma once

#include <glm/glm.hpp>

#include "world/brick_grid.h"

namespace engine::world {

struct BridgeParams {
    glm::ivec3 min{0}, max{0};  // the deck (max exclusive); it runs along the longer of x and z
    int railingHeight = 3;      // above the deck
    int postSpacing = 4;
    int lightSpacing = 8;  // 0 = no lights
    MaterialId deck = kEmpty, railing = kEmpty, light = kEmpty;
};

// The number of light voxels the bridge gets.
int bridgeLightCount(const BridgeParams& p);
void generateBridge(BrickGrid& grid, const BridgeParams& p);

}  // namespace engine::world
