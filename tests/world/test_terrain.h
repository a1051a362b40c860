// A small generated terrain for the streaming and store tests: seeded, clipped at every far edge
// of its regions when the world size is not a multiple of 128.
#pragma once

#include "world/generators.h"

namespace vox_test {

inline engine::world::TerrainParams testTerrain(std::uint32_t seed = 7) {
    engine::world::TerrainParams p;
    p.top = 1;
    p.soil = 2;
    p.rock = 3;
    p.baseHeight = 96;
    p.amplitude = 64;
    p.wavelength = 90;
    p.octaves = 4;
    p.seed = seed;
    return p;
}

}  // namespace vox_test
