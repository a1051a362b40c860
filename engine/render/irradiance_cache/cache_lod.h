// Level of detail for the irradiance cache: which entry a static surface's face reads. Near the
// camera every visible voxel has its own entry (six faces). Farther than `lodDistance` along the
// view ray, a face may instead share a coarse entry with three others: one face of a 2x2 patch
// of static voxels in one plane, aligned to even coordinates, whose four voxels in front are all
// empty. Only such fully open, coplanar patches are coarse, so no one-voxel wall can stand between
// two faces of one entry, nor between two neighbouring coarse entries (their fronts touch); where
// the patch is not open the voxel keeps its fine entry. The gather (shaders/irradiance_cache/
// gather.glsl, gatherPixel) applies the same rule per pixel.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "render/irradiance_cache/irradiance_cache_directory.h"
#include "world/brick_grid.h"

namespace engine::render {

// The lowest voxel of the 2x2 patch of `face` that holds `voxel` (even coordinates in the face's
// plane).
glm::ivec3 coarsePatchBase(glm::ivec3 voxel, std::uint32_t face);

// The coarse key of `face` of static voxel `voxel` if its 2x2 patch is open, else nothing. Every
// voxel of one patch gets the same answer.
std::optional<CacheKey> coarsePatchKey(const world::BrickGrid& grid, glm::ivec3 voxel,
                                       std::uint32_t face);

// The key a static pixel at `viewDistance` reads: coarse when LOD is on, the pixel is at least
// `lodDistance` away and its patch is open; otherwise the voxel's own.
CacheKey staticKeyFor(const world::BrickGrid& grid, glm::ivec3 voxel, std::uint32_t face,
                      float viewDistance, float lodDistance);

// staticKeyFor over the pixels of a frame in scan order: neighbouring far pixels mostly lie in
// one patch, so the last patch's answer is kept and the grid read again only for a new patch.
class StaticKeys {
public:
    StaticKeys(const world::BrickGrid& grid, float lodDistance)
        : mGrid(grid), mLodDistance(lodDistance) {}
    CacheKey keyFor(glm::ivec3 voxel, std::uint32_t face, float viewDistance);

private:
    const world::BrickGrid& mGrid;
    float mLodDistance;
    glm::ivec4 mPatch{-1};  // base and face of the last patch asked about
    bool mPatchOpen = false;
};

}  // namespace engine::render
