#include "world/terrain_region_source.h"

#include "world/height_field.h"

namespace engine::world {

TerrainRegionSource::TerrainRegionSource(glm::ivec3 worldSizeInVoxels, const TerrainParams& params)
    : mSizeInCells((worldSizeInVoxels + (kBrickDim - 1)) / kBrickDim), mParams(params) {}

Result<RegionSnapshot> TerrainRegionSource::load(RegionKey key) {
    const CellRange range = regionCells(key, mSizeInCells);
    if (glm::any(glm::lessThanEqual(range.size(), glm::ivec3(0))))
        return makeError("region ({}, {}, {}) lies outside the world", key.x, key.y, key.z);
    // A grid of the region alone (a few MiB at most, freed on return), then its snapshot.
    BrickGrid local(range.size() * kBrickDim);
    fillHeightFieldAt(
        local, [&](int x, int z) { return terrainHeight(mParams, x, z); }, terrainColumns(mParams),
        range.min);
    RegionSnapshot s = snapshotRegion(local, RegionKey{}, kRegionCells);
    s.key = key;
    return s;
}

}  // namespace engine::world
