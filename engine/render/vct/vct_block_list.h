// VctBlockList: the blocks of 4^3 texels (shared/vct.h: VCT_BLOCK) vct.classify visits in a frame,
// made on the host so that the injection's cost follows what changed, not the clipmap's size.
// A block is listed when one of its texels may need a value other than its slot holds: the texels
// new to a level (their slot held another world texel), and — while the rotation can change
// anything — the blocks that hold an occupied 8^3 cell or meet the objects' box. Empty space that
// stays in a level keeps its zeros and costs nothing; VoxelConeTracing::prepare decides which of
// these a frame needs (render/vct/voxel_cone_tracing.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "shared/vct.h"
#include "world/brick_grid.h"

namespace engine::render {

class VctBlockList {
public:
    VctBlockList();

    // Starts this frame's list: nothing listed.
    void clear();
    // Every block of the first `levels` levels.
    void addAll(std::uint32_t levels);
    // The blocks of `level`, placed at `now` (xyz its minimum corner in voxels, w its texel size),
    // that hold a texel outside the level placed at `before`: their slots held other world texels.
    void addNew(std::uint32_t level, glm::ivec4 now, glm::ivec4 before);
    // The blocks of `level` placed at `now` that meet the box [boxMin, boxMax) of voxels.
    void addBox(std::uint32_t level, glm::ivec4 now, glm::ivec3 boxMin, glm::ivec3 boxMax);
    // The blocks of `level` placed at `now` that hold an occupied 8^3 cell of `grid` (a superset
    // of the texels vct.classify finds occupied). Kept per level while the placement and
    // `gridVersion` (changed whenever the grid's cells may have) stay.
    void addContent(std::uint32_t level, glm::ivec4 now, const world::BrickGrid& grid,
                    std::uint64_t gridVersion);

    // The listed blocks in index order (shared/vct.h's block index).
    std::span<const std::uint32_t> blocks();

    // Whether the voxel box [lo, hi) holds a non-empty 8^3 cell of `grid`: super cells first.
    static bool holdsCell(const world::BrickGrid& grid, glm::ivec3 lo, glm::ivec3 hi);

private:
    struct ContentCache {
        bool valid = false;
        glm::ivec4 placement{0};
        std::uint64_t gridVersion = 0;
        std::vector<std::uint8_t> holds;  // per block of the level
    };
    std::vector<std::uint8_t> mListed;  // per block of every level
    std::vector<std::uint32_t> mBlocks;
    std::array<ContentCache, shared::VCT_MAX_LEVELS> mContent;
};

}  // namespace engine::render
