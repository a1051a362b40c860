// Player collision: an axis-aligned box against the world's voxels — the static BrickGrid and
// this frame's DynamicGrid (world/dynamic_grid.h) — read voxel by voxel through their own
// get(), so there is no second world representation to keep in step with edits.
//
// A move is swept one axis at a time over exactly the voxel layers the box's leading face
// enters, nearest first, and stops kSkin short of the first layer with a solid voxel under the
// box's cross-section: it cannot tunnel through a one-voxel wall whatever the distance. Layers
// the box already overlaps are not checked, so a box that something moved into can still move
// out. Outside the world's sides and below its floor counts as solid; above its top is open sky,
// so a sweep reads only the layers between the floor and the highest solid voxel (the world's
// top, or a dynamic object's): its work is bounded by the world, never by the distance.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "world/brick_grid.h"
#include "world/dynamic_grid.h"

namespace engine::world {

// The gap a blocked move leaves before the solid face: large against the rounding of positions
// up to the largest world (8192 voxels: 1e-12), small against anything a player sees.
inline constexpr double kSkin = 1e-5;

// In voxel units; voxel v fills [v, v + 1). Touching a face is not overlapping.
struct PlayerBox {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
};

// The voxel holding coordinate v, saturated at +-2^30 (far beyond any world), so that no
// position -- infinite, 1e30, NaN (taken as -2^30) -- converts to an out-of-range int.
int voxelFloor(double v);

// The voxels a box overlaps (max exclusive); empty for an empty box.
Box overlappedVoxels(const PlayerBox& box);

struct CollisionWorld {
    const BrickGrid& grid;
    const DynamicGrid* dynamic = nullptr;  // this frame's objects, or none
    // Voxels read through solid(): the collision's work, which tests bound (steps, not time).
    mutable std::uint64_t voxelReads = 0;

    bool solid(glm::ivec3 voxel) const;
    bool dynamicAt(glm::ivec3 voxel) const { return dynamic && dynamic->get(voxel) != kEmpty; }
    // One above the highest layer that can hold a solid voxel: the world's top or the objects'.
    int solidTop() const;
};

bool overlapsSolid(const CollisionWorld& world, const PlayerBox& box);

// Moves `box` along `axis` (0 x, 1 y, 2 z) by up to `distance` voxels and returns how far it
// went (same sign, never further; 0 when the first layer entered is solid).
double sweepAxis(const CollisionWorld& world, PlayerBox& box, int axis, double distance);

}  // namespace engine::world
