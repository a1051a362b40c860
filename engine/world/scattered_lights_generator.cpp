#include "world/scattered_lights_generator.h"

#include <algorithm>

#include "core/hash.h"
#include "world/generators.h"
#include "world/world_edits.h"

namespace engine::world {

int generateScatteredLights(BrickGrid& grid, const ScatteredLightsParams& p) {
    const glm::ivec3 world = grid.sizeInVoxels();
    const int nx = (world.x - 2 * p.margin) / p.spacing, nz = (world.z - 2 * p.margin) / p.spacing;
    Rng rng(p.seed);
    int placed = 0;
    for (int gz = 0; gz < nz; ++gz)
        for (int gx = 0; gx < nx; ++gx) {
            // Drawn for every cell, placed or not, so a change elsewhere never shifts the others.
            int ox = rng.uniformInt(0, p.spacing - p.size.x),
                oz = rng.uniformInt(0, p.spacing - p.size.z);
            glm::ivec3 lo{p.margin + gx * p.spacing + ox, 0, p.margin + gz * p.spacing + oz};
            for (int z = 0; z < p.size.z; ++z)
                for (int x = 0; x < p.size.x; ++x)
                    lo.y = std::max(lo.y, groundHeight(grid, lo.x + x, lo.z + z));
            if (lo.y + p.size.y > world.y) continue;
            fillBox(grid, Box{lo, lo + p.size}, p.light);
            ++placed;
        }
    return placed;
}

}  // namespace engine::world
