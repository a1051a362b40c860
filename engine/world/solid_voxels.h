// Walking what a BrickGrid holds, in storage order: its occupied cells (x fastest, then y,
// then z), or the solid voxels in them (x fastest within each cell). Empty cells cost one read
// of the top grid; their bricks are never touched.
#pragma once

#include "world/brick_grid.h"

namespace engine::world {

// f(cell) for every cell that is not empty: a brick or a homogeneous cell. A run of cells in a
// region without a top-grid page of its own (all empty) is skipped in one step.
template <typename F>
void forEachOccupiedCell(const BrickGrid& grid, F&& f) {
    const glm::ivec3 cells = grid.sizeInCells();
    const PagedTopGrid& top = grid.topGrid();
    for (int cz = 0; cz < cells.z; ++cz)
        for (int cy = 0; cy < cells.y; ++cy)
            for (int cx = 0; cx < cells.x;) {
                const glm::ivec3 c(cx, cy, cz);
                if (!top.regionHasPage(c)) {
                    cx = (cx | (kRegionCells - 1)) + 1;
                    continue;
                }
                if (top.get(c) != shared::CELL_EMPTY) f(c);
                ++cx;
            }
}

// f(voxel, material) for every voxel that is not empty.
template <typename F>
void forEachSolidVoxel(const BrickGrid& grid, F&& f) {
    forEachOccupiedCell(grid, [&](glm::ivec3 c) {
        const BrickVoxels voxels = grid.readCell(c);
        for (int i = 0; i < kBrickVoxels; ++i) {
            const MaterialId m = voxels[std::size_t(i)];
            if (m != kEmpty) f(c * kBrickDim + brickVoxelPosition(i), m);
        }
    });
}

}  // namespace engine::world
