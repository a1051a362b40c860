// TerrainRegionSource: the terrain generator (world/generators.h) run one region at a time, so a
// world of any width is generated lazily where the camera goes. A region comes out cell for cell
// as the whole-world generator writes it (height_field.h's fillHeightFieldAt decides every cell
// from world coordinates), which tests/world/region_residency_test.cpp checks.
#pragma once

#include "world/generators.h"
#include "world/region_source.h"

namespace engine::world {

class TerrainRegionSource : public RegionSource {
public:
    TerrainRegionSource(glm::ivec3 worldSizeInVoxels, const TerrainParams& params);
    glm::ivec3 worldSizeInCells() const override { return mSizeInCells; }
    Result<RegionSnapshot> load(RegionKey key) override;

private:
    glm::ivec3 mSizeInCells;
    TerrainParams mParams;
};

}  // namespace engine::world
