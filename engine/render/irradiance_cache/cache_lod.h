// Level of detail for the irradiance cache: which entry a static surface's face reads. Near the
// camera every visible voxel has its own entry (six faces). Farther than `lodDistance` along the
// view ray, a face may instead share a coarse entry with three others: one face of a 2x2 patch
// of static voxels in one plane, aligned to even coordinates, whose four voxels in front are all
// empty. Only such fully open, coplanar patches are coarse, so no one-voxel wall can stand between
// two faces of one entry, nor between two neighbouring coarse entries (their fronts touch); where
// the patch is not open the voxel keeps its fine entry. The gather (shaders/irradiance_cache/
// gather.comp, cacheCoarseKeyFor) applies the same rule per pixel.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "render/irradiance_cache/irradiance_cache_directory.h"
#include "world/brick_grid.h"

namespace engine::render {

// The coarse key of `face` of static voxel `voxel` if its 2x2 patch is open, else nothing.
std::optional<CacheKey> coarsePatchKey(const world::BrickGrid& grid, glm::ivec3 voxel, std::uint32_t face);

// The key a static pixel at `viewDistance` reads: coarse when LOD is on, the pixel is at least
// `lodDistance` away and its patch is open; otherwise the voxel's own.
CacheKey staticKeyFor(const world::BrickGrid& grid, glm::ivec3 voxel, std::uint32_t face, float viewDistance,
                      float lodDistance);

}  // namespace engine::render
