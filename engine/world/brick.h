// One 8^3 brick: material ids (x fastest) and its occupancy masks at three resolutions
// (voxel, 2^3 block, 4^3 block) that let traversal skip empty space inside the brick.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "shared/brick_grid.h"
#include "world/material.h"

namespace engine::world {

inline constexpr int kBrickDim = static_cast<int>(shared::BRICK_DIM);
inline constexpr int kBrickVoxels = static_cast<int>(shared::BRICK_VOXELS);

using BrickVoxels = std::array<MaterialId, kBrickVoxels>;

constexpr int brickVoxelIndex(glm::ivec3 local) { return local.x + 8 * local.y + 64 * local.z; }
// The voxel a brick holds at `index`: the inverse of brickVoxelIndex.
constexpr glm::ivec3 brickVoxelPosition(int index) {
    return {index & 7, (index >> 3) & 7, index >> 6};
}

struct BrickMask {
    std::array<std::uint32_t, shared::BRICK_MASK_WORDS> words{};

    static BrickMask build(const BrickVoxels& voxels);
    bool voxel(glm::ivec3 local) const {
        int bit = brickVoxelIndex(local);
        return (words[bit >> 5] >> (bit & 31)) & 1u;
    }
    bool block2(glm::ivec3 local) const {
        glm::ivec3 b = local >> 1;
        int bit = b.x + 4 * b.y + 16 * b.z;
        return (words[shared::MASK_COARSE_WORD + (bit >> 5)] >> (bit & 31)) & 1u;
    }
    bool block4(glm::ivec3 local) const {
        glm::ivec3 b = local >> 2;
        return (words[shared::MASK_QUARTER_WORD] >> (b.x + 2 * b.y + 4 * b.z)) & 1u;
    }
    bool operator==(const BrickMask&) const = default;
};

// True when all 512 voxels hold the same id.
bool isUniform(const BrickVoxels& voxels);

}  // namespace engine::world
