// What `vox info` reports about a world: dimensions, brick counts, voxels, emitters, and the
// bytes each structure uses on the CPU and (when uploaded) on the GPU.
#pragma once

#include <cstdint>
#include <string>

#include "world/scene.h"

namespace engine::world {

struct WorldInfo {
    glm::ivec3 sizeInVoxels{0};
    glm::ivec3 sizeInCells{0};
    std::uint64_t cells = 0;
    std::uint64_t emptyCells = 0;
    std::uint64_t homogeneousCells = 0;
    std::uint64_t bricks = 0;      // live bricks in the pool
    std::uint64_t freeBricks = 0;  // freed, awaiting reuse
    std::uint64_t solidVoxels = 0;
    std::uint64_t emissiveVoxels = 0;
    std::size_t materials = 0;
    std::size_t topGridBytes = 0;
    std::size_t superGridBytes = 0;
    std::size_t brickPoolBytes = 0;
    std::size_t paletteBytes = 0;
    std::size_t bookkeepingBytes = 0;
    std::size_t totalBytes() const {
        return topGridBytes + superGridBytes + brickPoolBytes + paletteBytes + bookkeepingBytes;
    }
};

WorldInfo describeWorld(const Scene& scene);

// Human-readable and JSON forms.
std::string formatWorldInfo(const WorldInfo& info, const std::string& title);
std::string worldInfoJson(const WorldInfo& info);

}  // namespace engine::world
