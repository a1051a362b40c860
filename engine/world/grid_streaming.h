// GridStreaming: a world larger than memory played through a BrickGrid sized to the whole world
// that holds only the regions a RegionResidency (world/region_residency.h) keeps around the eye.
// A region that arrives or leaves is written into the grid like an edit — cells and bricks through
// the same dirty lists — so the GPU mirror, the emitter list, ReGIR, the irradiance cache and DVF
// all see it as one (render/frame_changes.h), but without the edit stamp a save writes
// (BrickGrid::setStampingEdits): what was only streamed is never saved.
//
// The residency's loader thread reads, decodes or generates a region; the frame thread only copies
// it into the grid, nearest first, at most `regionsPerFrame` regions and `bricksPerFrame` bricks a
// frame (but always one region, however many bricks it has), so a frame's share of streaming is
// bounded: the copy, and everything downstream (uploads, the emitter rescan, the lighting's
// invalidation), grows with the bricks and cells written. Bricks, not milliseconds: the split of
// arrivals over frames then depends on what arrived, not on how loaded the machine is. A region
// is written whole or not at all, so a ray sees it whole or as air, never half. The residency's
// copy is handed back to be freed once the grid holds it: the budget counts the bytes the grid
// holds for streamed regions, not a second copy.
//
// Regions not in the grid are air for rays (the grid's empty cells) and must not be walked into:
// boxInGrid() says whether every region a box meets is there (the player waits while not).
// Edited regions are pinned by the caller (pin()) until their save commits, so an edit is never
// evicted before it is on disk; after that, eviction and reload give it back from the store.
//
// The grid's top grid is paged by region (world/paged_top_grid.h): a region that leaves gives its
// page back once the frame's changes have been seen (BrickGrid::clearDirty), so the top grid, CPU
// and GPU, holds pages for the regions in the grid only. What stays sized to the world is the
// region table (4 bytes a region) and the super grid (6 bytes per 32^3 voxels on the CPU, 4 on the
// GPU: 24 + 16 MiB at 16384 x 512 x 16384).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "world/brick_grid.h"
#include "world/region_residency.h"

namespace engine::world {

struct GridStreamingReport {
    std::size_t arrived = 0;          // regions written into the grid by this update
    std::size_t left = 0;             // regions erased from the grid by this update
    std::size_t bricks = 0;           // bricks of the regions written in by this update
    std::size_t waiting = 0;          // loaded, not yet in the grid (the per-frame limits)
    std::size_t pending = 0;          // asked of the loader, not loaded yet
    double inMs = 0.0;                // copying arrived regions into the grid
    double outMs = 0.0;               // erasing left regions from the grid
    std::vector<std::string> errors;  // regions that failed to load (empty), one line each
};

class GridStreaming {
public:
    static constexpr std::size_t kUnlimitedBricks = ~std::size_t(0);
    GridStreaming(std::unique_ptr<RegionSource> source, const ResidencySettings& settings,
                  std::size_t regionsPerFrame, std::size_t bricksPerFrame = kUnlimitedBricks);

    // Frame thread, once a frame: the residency's update around `eye`, then the grid follows it.
    GridStreamingReport update(glm::vec3 eye, BrickGrid& grid);
    // Regions the budget must not evict (edited and not yet saved); replaces the previous set.
    void pin(std::span<const RegionKey> keys) { mResidency.setPinned(keys); }

    bool inGrid(RegionKey key) const { return mInGrid[index(key)] != 0; }
    // Every region the box of voxels meets (clipped to the world) is in the grid.
    bool boxInGrid(const Box& voxels) const;
    std::size_t regionsInGrid() const { return mGridKeys.size(); }
    std::uint64_t bytes() const { return mResidency.residentBytes(); }
    const ResidencySettings& settings() const { return mResidency.settings(); }
    std::size_t regionsPerFrame() const { return mRegionsPerFrame; }
    std::size_t bricksPerFrame() const { return mBricksPerFrame; }
    RegionResidency& residency() { return mResidency; }

private:
    std::size_t index(RegionKey k) const {
        const glm::ivec3 n = mResidency.regionCounts();
        return std::size_t(k.x) + std::size_t(n.x) * (std::size_t(k.y) + std::size_t(n.y) * k.z);
    }

    RegionResidency mResidency;
    std::size_t mRegionsPerFrame;
    std::size_t mBricksPerFrame;
    std::vector<std::uint8_t> mInGrid;  // per region
    std::vector<RegionKey> mGridKeys;   // the regions in the grid
};

}  // namespace engine::world
