// ResidentRegion: one region held in memory by the streaming residency (world/region_residency.h)
// — its 16^3 cells and exactly its bricks with their occupancy masks, sized to what it holds (a
// region-sized BrickGrid would reserve a 4096-brick pool page, 4.3 MiB, for a few hundred bricks).
// The cells use the region codec's encoding (world/region_codec.h: 0 empty, 0x80000000|material
// homogeneous, k the k-th brick), so a region loaded from a store is its decoded row as is.
#pragma once

#include <cstddef>
#include <vector>

#include "world/brick.h"
#include "world/region_codec.h"

namespace engine::world {

class ResidentRegion {
public:
    explicit ResidentRegion(RegionSnapshot voxels);  // builds the masks

    const RegionSnapshot& voxels() const { return mVoxels; }
    RegionKey key() const { return mVoxels.key; }
    // The material at world voxel `p`, which must lie in the region.
    MaterialId get(glm::ivec3 p) const;
    const BrickMask& brickMask(std::uint32_t k) const { return mMasks[k - 1]; }  // k in 1..B
    // Heap bytes held (cells, bricks, masks): what the residency's budget counts.
    std::size_t bytes() const;

private:
    RegionSnapshot mVoxels;
    std::vector<BrickMask> mMasks;
    glm::ivec3 mOriginVoxel{0};
};

}  // namespace engine::world
