// The dynamic brick grid: every dynamic object re-voxelised, world-aligned, into one small
// sparse BrickGrid covering only the union of their world bounds.
//
// Rebuilt on the CPU each frame the poses change (updateDynamicObjects), uploaded whole by
// render/gpu_dynamic_grid.h (it is small) and traced by every ray next to the static world
// (world/scene_trace.h, shaders/common/scene_trace.glsl). Sampling is nearest: each world voxel
// whose centre the inverse transform maps into a model voxel takes that voxel's material, so a
// rotation by 90 degrees or a translation by whole voxels reproduces the model exactly.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "world/brick_grid.h"
#include "world/dynamic_object.h"

namespace engine::world {

// What motion vectors need of one object this frame.
struct DynamicInstance {
    Box bounds;                     // world voxels it may cover (its transformed model box)
    glm::dmat4 worldFromModel;      // this frame
    glm::dmat4 prevWorldFromModel;  // last frame
    // Maps a point on the object now to where the same material point was last frame.
    glm::dmat4 prevFromCurrent() const { return prevWorldFromModel * glm::inverse(worldFromModel); }
};

struct DynamicGrid {
    BrickGrid grid{glm::ivec3(8)};
    glm::ivec3 origin{0};                    // world voxel of grid voxel (0,0,0); brick-aligned
    std::vector<DynamicInstance> instances;  // one per object, in scene order
    // The coarse occupancy: at most shared::DYNAMIC_OCCUPANCY_BOXES boxes of whole cells (world
    // voxels, max exclusive) that together hold every voxel of the grid — the cells each object
    // wrote into, object i in box i mod that count. A ray that comes within a voxel of none of
    // them skips the dynamic traversal (traceDynamic), so a ray far from every object pays one
    // box test per object rather than a traversal of the grid over their union.
    std::vector<Box> occupancy;
    std::uint64_t revision = 0;  // changes whenever the grid is rebuilt

    bool present() const { return !instances.empty(); }
    // Material at a world voxel (kEmpty outside).
    MaterialId get(glm::ivec3 world) const { return present() ? grid.get(world - origin) : kEmpty; }
};

// Voxelises the objects at their `current` poses. Where objects overlap the first one wins.
DynamicGrid voxelizeObjects(std::span<const DynamicObject> objects);

// Poses every object at `time` (current) and `prevTime` (previous) and rebuilds `grid` if any
// pose changed (its revision then counts up). Returns whether it rebuilt.
bool updateDynamicObjects(std::vector<DynamicObject>& objects, DynamicGrid& grid, double time,
                          double prevTime);

}  // namespace engine::world
