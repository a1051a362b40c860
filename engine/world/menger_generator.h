// A Menger sponge: the "complex geometry in the middle" of the thesis's emissive letters scene.
// Tunnels at every scale make many small occluders, corners and openings, which is what
// stresses visibility reuse in ReSTIR.
#pragma once

#include <glm/glm.hpp>

#include "world/brick_grid.h"

namespace engine::world {

struct MengerParams {
    glm::ivec3 origin{0};  // lower corner
    int level = 3;         // edge = 3^level x scale voxels
    int scale = 1;         // voxels per unit cube of the finest level
    MaterialId material = kEmpty;
};

inline int mengerEdge(const MengerParams& p) {
    int edge = p.scale;
    for (int i = 0; i < p.level; ++i) edge *= 3;
    return edge;
}
// Solid voxels of the sponge: 20^level x scale^3.
long long mengerVoxelCount(const MengerParams& p);
// Writes the whole cube: the sponge's material where it is solid, empty in its tunnels.
void generateMenger(BrickGrid& grid, const MengerParams& p);

}  // namespace engine::world
