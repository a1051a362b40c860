// Region edits on a BrickGrid. Each works brick by brick: a cell fully covered by the edit and
// uniform before it stays a homogeneous cell (no storage); a partly covered one is split into a
// brick, edited, and collapsed again if it ends up uniform. Only cells that change are dirtied.
#pragma once

#include <glm/glm.hpp>

#include "world/brick_grid.h"

namespace engine::world {

void fillBox(BrickGrid& grid, const Box& box, MaterialId material);
// Voxels whose centre lies within `radius` of `center` (in voxel units).
void fillSphere(BrickGrid& grid, glm::vec3 center, float radius, MaterialId material);
// The voxels fillSphere/paintSphere may touch.
Box sphereBounds(glm::vec3 center, float radius);
// Painting: solid voxels in the shape take `material`; empty space stays empty.
void paintBox(BrickGrid& grid, const Box& box, MaterialId material);
void paintSphere(BrickGrid& grid, glm::vec3 center, float radius, MaterialId material);
// Within `region`, every voxel of material `from` becomes `to`.
void replaceMaterial(BrickGrid& grid, const Box& region, MaterialId from, MaterialId to);

// Copies `region` into a new grid whose origin is region.min.
BrickGrid copyRegion(const BrickGrid& grid, const Box& region);
// Writes `clip` with its origin at `at`; with skipEmpty, empty clip voxels leave the target as is.
void pasteRegion(BrickGrid& grid, const BrickGrid& clip, glm::ivec3 at, bool skipEmpty);

}  // namespace engine::world
