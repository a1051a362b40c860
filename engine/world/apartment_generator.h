// One floating apartment block (the thesis's flying apartments scene): a storeyed shell with
// floor slabs and a stair core, window rows whose lit panes are emissive in several colours
// (unlit ones are open), balconies with railings, neon strips down the corners, a roof with a
// parapet and a stair house, and a chunk of rock torn from the ground hanging underneath.
// Everything is a seeded function of the parameters.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "world/brick_grid.h"

namespace engine::world {

struct ApartmentParams {
    glm::ivec3 min{0};            // lower corner of the bottom slab
    glm::ivec3 size{32, 48, 32};  // footprint and height
    int storey = 8;               // floor-to-floor height
    glm::ivec2 windowSize{3, 4};  // width, height
    int windowSpacing = 6;        // along a facade, window to window
    float lit = 0.6f;             // fraction of windows that are lit (emissive panes)
    float balconies = 0.2f;       // fraction of unlit windows that get a balcony
    int baseDepth = 24;           // depth of the rock underneath (0 = none)
    std::uint32_t seed = 1;
    MaterialId wall = kEmpty, slab = kEmpty, railing = kEmpty, base = kEmpty;
    MaterialId cornerLight = kEmpty;       // neon strips on the vertical edges (kEmpty = none)
    std::vector<MaterialId> windowLights;  // lit panes pick one of these
};

void generateApartment(BrickGrid& grid, const ApartmentParams& p);

}  // namespace engine::world
