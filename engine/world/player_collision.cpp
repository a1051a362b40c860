#include "world/player_collision.h"

#include <algorithm>
#include <cmath>

namespace engine::world {

namespace {

constexpr int kFar = 1 << 30;

int voxelCeil(double v) {
    if (!(v > -kFar)) return -kFar;  // NaN too: a NaN box is empty
    if (!(v < kFar)) return kFar;
    return int(std::ceil(v));
}

}  // namespace

int voxelFloor(double v) {
    if (!(v > -kFar)) return -kFar;  // NaN too
    if (!(v < kFar)) return kFar;
    return int(std::floor(v));
}

Box overlappedVoxels(const PlayerBox& box) {
    return {glm::ivec3(voxelFloor(box.min.x), voxelFloor(box.min.y), voxelFloor(box.min.z)),
            glm::ivec3(voxelCeil(box.max.x), voxelCeil(box.max.y), voxelCeil(box.max.z))};
}

int CollisionWorld::solidTop() const {
    int top = grid.sizeInVoxels().y;
    if (dynamic && dynamic->present())
        top = std::max(top, dynamic->origin.y + dynamic->grid.sizeInVoxels().y);
    return top;
}

bool CollisionWorld::solid(glm::ivec3 v) const {
    ++voxelReads;
    const glm::ivec3 size = grid.sizeInVoxels();
    if (v.x < 0 || v.z < 0 || v.x >= size.x || v.z >= size.z || v.y < 0)
        return true;                         // the world's walls
    if (grid.get(v) != kEmpty) return true;  // above the top get() is empty: sky
    return dynamicAt(v);
}

bool overlapsSolid(const CollisionWorld& world, const PlayerBox& box) {
    const Box voxels = overlappedVoxels(box);
    for (int z = voxels.min.z; z < voxels.max.z; ++z)
        for (int y = voxels.min.y; y < voxels.max.y; ++y)
            for (int x = voxels.min.x; x < voxels.max.x; ++x)
                if (world.solid({x, y, z})) return true;
    return false;
}

namespace {

// Whether any voxel of layer `index` along `axis`, under the box's cross-section, is solid.
bool layerSolid(const CollisionWorld& world, const Box& voxels, int axis, int index) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    glm::ivec3 v;
    v[axis] = index;
    for (v[b] = voxels.min[b]; v[b] < voxels.max[b]; ++v[b])
        for (v[a] = voxels.min[a]; v[a] < voxels.max[a]; ++v[a])
            if (world.solid(v)) return true;
    return false;
}

}  // namespace

double sweepAxis(const CollisionWorld& world, PlayerBox& box, int axis, double distance) {
    if (distance == 0.0 || !std::isfinite(distance)) return 0.0;
    const Box voxels = overlappedVoxels(box);
    // Sideways the world's walls and downwards its floor are solid, so a sweep that way stops
    // within the world; upwards nothing is solid above solidTop(): the layers there are skipped.
    const int top = axis == 1 ? world.solidTop() - 1 : INT32_MAX;
    double moved = distance;
    if (distance > 0.0) {
        // Layers from the first one past the box's current extent to the last the move reaches.
        const int first = voxelCeil(box.max[axis]);
        const int last = std::min(voxelCeil(box.max[axis] + distance) - 1, top);
        for (int i = first; i <= last; ++i) {
            if (layerSolid(world, voxels, axis, i)) {
                moved = std::clamp(double(i) - kSkin - box.max[axis], 0.0, distance);
                break;
            }
        }
    } else {
        const int first = std::min(voxelFloor(box.min[axis]) - 1, top);
        const int last = voxelFloor(box.min[axis] + distance);
        for (int i = first; i >= last; --i) {
            if (layerSolid(world, voxels, axis, i)) {
                moved = std::clamp(double(i + 1) + kSkin - box.min[axis], distance, 0.0);
                break;
            }
        }
    }
    box.min[axis] += moved;
    box.max[axis] += moved;
    return moved;
}

}  // namespace engine::world
