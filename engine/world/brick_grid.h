// BrickGrid: the two-level voxel world.
//
// A top grid over the world's bounds in 8^3 cells holds one uint per cell (encoding in
// shaders/shared/brick_grid.h): empty, homogeneous (one material, no storage) or an index into a
// brick pool with a free list. The top grid is paged by region (world/paged_top_grid.h): regions
// without a non-empty cell share one empty page, so its memory follows content. Random access is
// O(1) (a table read, then the page's). Every write that changes a brick
// or a cell marks it dirty; the GPU mirror (render/gpu_world.h) uploads only dirty entries and
// then calls clearDirty(). Uniform bricks collapse back into homogeneous cells on write.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "world/brick.h"
#include "world/paged_pool.h"
#include "world/paged_top_grid.h"
#include "world/region.h"

namespace engine::world {

// Integer box of voxels, min inclusive, max exclusive.
struct Box {
    glm::ivec3 min{0};
    glm::ivec3 max{0};
    bool empty() const { return glm::any(glm::lessThanEqual(max, min)); }
    glm::ivec3 size() const { return max - min; }
    bool contains(glm::ivec3 p) const {
        return glm::all(glm::greaterThanEqual(p, min)) && glm::all(glm::lessThan(p, max));
    }
    Box intersect(const Box& o) const { return {glm::max(min, o.min), glm::min(max, o.max)}; }
};

struct GridMemory {
    std::size_t topGridBytes = 0;  // region table and pages, with each page's dirty marks
    std::size_t superGridBytes =
        0;  // skip distances and counts over 4^3 cells (5/256 of the top grid)
    std::size_t brickPoolBytes = 0;    // capacity of the pool (live + free bricks), voxels + masks
    std::size_t liveBrickBytes = 0;    // live bricks only
    std::size_t bookkeepingBytes = 0;  // free list and dirty lists
};

class BrickGrid {
public:
    // The world spans [0, sizeInVoxels) rounded up to whole cells.
    explicit BrickGrid(glm::ivec3 sizeInVoxels);

    glm::ivec3 sizeInCells() const { return mSizeInCells; }
    glm::ivec3 sizeInSuperCells() const { return mSizeInSuperCells; }
    glm::ivec3 sizeInVoxels() const { return mSizeInCells * kBrickDim; }
    Box bounds() const { return {glm::ivec3(0), sizeInVoxels()}; }
    bool contains(glm::ivec3 p) const { return bounds().contains(p); }
    bool containsCell(glm::ivec3 c) const {
        return glm::all(glm::greaterThanEqual(c, glm::ivec3(0))) &&
               glm::all(glm::lessThan(c, mSizeInCells));
    }

    // Voxel access. Reads outside the world return kEmpty; writes outside are ignored.
    MaterialId get(glm::ivec3 p) const;
    void set(glm::ivec3 p, MaterialId material);

    // Cell access, for edits and traversal. A cell's index (x fastest, as if the top grid were
    // dense) names it in the dirty lists; storage is by page (topGrid()).
    std::size_t cellIndex(glm::ivec3 c) const {
        return static_cast<std::size_t>(c.x) +
               static_cast<std::size_t>(mSizeInCells.x) *
                   (static_cast<std::size_t>(c.y) + static_cast<std::size_t>(mSizeInCells.y) * c.z);
    }
    glm::ivec3 cellOfIndex(std::size_t index) const {
        const std::size_t yz = index / std::size_t(mSizeInCells.x);
        return {int(index % std::size_t(mSizeInCells.x)), int(yz % std::size_t(mSizeInCells.y)),
                int(yz / std::size_t(mSizeInCells.y))};
    }
    std::size_t cellCount() const {
        return std::size_t(mSizeInCells.x) * std::size_t(mSizeInCells.y) *
               std::size_t(mSizeInCells.z);
    }
    std::uint32_t cell(glm::ivec3 c) const { return mTop.get(c); }
    const PagedTopGrid& topGrid() const { return mTop; }
    // Every cell in index order, as a dense array (small grids: dynamic objects, tests).
    std::vector<std::uint32_t> denseCells() const;
    // Super cells (4^3 cells), for skipping open air: superCells() holds the skip distance of each
    // (0: something in it; k >= 1: empty within Chebyshev distance k - 1, see shared/brick_grid.h),
    // kept up to date on every edit from the count of non-empty cells in each.
    std::size_t superCellIndex(glm::ivec3 s) const {
        return static_cast<std::size_t>(s.x) +
               static_cast<std::size_t>(mSizeInSuperCells.x) *
                   (static_cast<std::size_t>(s.y) +
                    static_cast<std::size_t>(mSizeInSuperCells.y) * s.z);
    }
    std::span<const std::uint32_t> superCells() const { return mSuperCells; }
    std::span<const std::uint8_t> superCellCounts() const { return mSuperCounts; }
    BrickVoxels readCell(glm::ivec3 c) const;            // expands homogeneous cells
    void writeCell(glm::ivec3 c, const BrickVoxels& v);  // collapses uniform bricks
    void writeCellUniform(glm::ivec3 c, MaterialId material);

    static bool cellIsBrick(std::uint32_t cell) {
        return cell != shared::CELL_EMPTY && !(cell & shared::CELL_HOMOGENEOUS);
    }
    static std::uint32_t cellBrick(std::uint32_t cell) { return cell - 1u; }
    static MaterialId cellMaterial(std::uint32_t cell) {
        return cell == shared::CELL_EMPTY
                   ? kEmpty
                   : static_cast<MaterialId>(cell & shared::CELL_MATERIAL_MASK);
    }

    // Brick pool.
    const BrickVoxels& brickVoxels(std::uint32_t brick) const { return mBrickVoxels[brick]; }
    const BrickMask& brickMask(std::uint32_t brick) const { return mBrickMasks[brick]; }
    std::uint32_t brickCapacity() const { return static_cast<std::uint32_t>(mBrickVoxels.size()); }
    std::uint32_t liveBricks() const {
        return brickCapacity() - static_cast<std::uint32_t>(mFreeBricks.size());
    }
    std::uint32_t homogeneousCells() const;  // solid homogeneous cells (no storage)
    std::uint64_t solidVoxels() const;
    // Heap bytes of a pool of n bricks (voxels, masks, dirty flag), whole pages: what an importer
    // plans for its bricks.
    static std::uint64_t poolBytesFor(std::uint64_t bricks) {
        const std::uint64_t pages =
            (bricks + shared::BRICK_PAGE_BRICKS - 1) / shared::BRICK_PAGE_BRICKS;
        return pages * shared::BRICK_PAGE_BRICKS * (sizeof(BrickVoxels) + sizeof(BrickMask)) +
               bricks;
    }
    // Reserves bookkeeping for n bricks (the pool itself grows by pages and never regrows).
    void reserveBricks(std::uint32_t n);

    // Dirty tracking for the GPU mirror.
    std::span<const std::uint32_t> dirtyBricks() const { return mDirtyBricks; }
    std::span<const std::uint32_t> dirtyCells() const { return mDirtyCells; }
    std::span<const std::uint32_t> dirtySuperCells() const { return mDirtySuperCells; }
    // Cells whose voxels changed in any way (value or brick contents), for CPU-side consumers
    // such as the emitter list. Cleared with the rest by clearDirty().
    std::span<const std::uint32_t> touchedCells() const { return mTouchedCells; }
    void clearDirty();

    // Edits by region, for incremental saves (world/region.h): every change to a cell stamps its
    // region with the current edit epoch, never cleared by clearDirty(). A saver keeps the epoch
    // it last saved at: the regions edited since are those stamped later. Several savers (a save
    // and an autosave to another file) each keep their own.
    std::uint32_t editEpoch() const { return mEditEpoch; }
    // Ends the current epoch and returns it: edits from now on are stamped later.
    std::uint32_t closeEditEpoch() { return mEditEpoch++; }
    std::vector<RegionKey> regionsEditedAfter(std::uint32_t epoch) const;
    // Stamps regions with the current epoch again (the regions of a save that failed).
    void markRegionsEdited(std::span<const RegionKey> keys);
    // While off, changes are not stamped (they still mark cells and bricks dirty): streaming
    // (world/grid_streaming.h) writes a region that arrives or leaves like an edit, so the GPU
    // mirror and the lighting see it, but it is not an edit a save must write.
    void setStampingEdits(bool on) { mStampEdits = on; }

    GridMemory memory() const;
    bool operator==(const BrickGrid& other) const;  // same voxels, regardless of pool layout

private:
    std::uint32_t allocateBrick();
    void freeBrick(std::uint32_t brick);
    void setCell(glm::ivec3 c, std::uint32_t value);
    void markBrickDirty(std::uint32_t brick);
    void touchCell(glm::ivec3 c);
    void updateSkipDistances(glm::ivec3 changed, bool nowOccupied);
    std::uint32_t skipDistance(glm::ivec3 s) const;
    void setSuperCell(std::size_t index, std::uint32_t value);

    glm::ivec3 mSizeInCells;
    glm::ivec3 mSizeInSuperCells;
    PagedTopGrid mTop;                       // cells, and per cell kMarkDirty | kMarkTouched
    std::vector<std::uint32_t> mSuperCells;  // skip distances (what the GPU reads)
    std::vector<std::uint8_t> mSuperCounts;  // non-empty cells per super cell (0..64)
    std::vector<std::uint8_t> mSuperDirty;
    std::vector<std::uint32_t> mDirtySuperCells;
    // Paged like the GPU's brick pool, so growth never copies the pool.
    PagedPool<BrickVoxels, shared::BRICK_PAGE_SHIFT> mBrickVoxels;
    PagedPool<BrickMask, shared::BRICK_PAGE_SHIFT> mBrickMasks;
    std::vector<std::uint32_t> mFreeBricks;
    std::vector<std::uint8_t> mBrickDirty;
    std::vector<std::uint32_t> mDirtyBricks;
    std::vector<std::uint32_t> mDirtyCells;
    std::vector<std::uint32_t> mTouchedCells;
    glm::ivec3 mRegionCount;
    std::vector<std::uint32_t> mRegionStamp;  // edit epoch of each region's last change
    std::uint32_t mEditEpoch = 1;
    bool mStampEdits = true;
};

}  // namespace engine::world
