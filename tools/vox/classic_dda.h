// The baseline the engine's traversal is measured against: a classic two-level DDA
// (Amanatides & Woo 1987), incremental (tMax += tDelta), over 8^3 cells and then voxel by voxel
// inside non-empty bricks — no super cells, no occupancy levels. Written for speed (flat arrays,
// conditional moves for the axis choice), so the comparison is with a fast native DDA, not a
// naive one.
// Benchmark code only: the engine's reference is engine/world/ray_traversal.h.
#pragma once

#include "world/ray_traversal.h"

namespace vox {

engine::world::RayHit traceClassicTwoLevel(const engine::world::BrickGrid& grid,
                                           const engine::world::Ray& ray);

}  // namespace vox
