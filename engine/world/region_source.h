// RegionSource: where a streamed world's regions come from (world/region_residency.h). A source
// gives one region's voxels by key, alone — from a region store (world/store_region_source.h) or
// generated on demand (world/terrain_region_source.h) — and the same voxels every time for the
// same key, whatever was asked before: streaming is then free to load, evict and reload regions
// in any order. load() runs on the residency's loader thread, one call at a time.
#pragma once

#include <glm/glm.hpp>

#include "core/error.h"
#include "world/region.h"
#include "world/region_codec.h"

namespace engine::world {

class RegionSource {
public:
    virtual ~RegionSource() = default;
    virtual glm::ivec3 worldSizeInCells() const = 0;
    // The region's cells and bricks, its size clipped to the world (RegionSnapshot numbering:
    // bricks in cell order, so equal voxels give equal snapshots). An empty region has every cell
    // CELL_EMPTY. A failure (a damaged row) is one line naming the region.
    virtual Result<RegionSnapshot> load(RegionKey key) = 0;
};

}  // namespace engine::world
