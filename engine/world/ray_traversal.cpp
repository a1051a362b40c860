#include "world/ray_traversal.h"

#include <algorithm>
#include <cmath>

namespace engine::world {

namespace {

RayHit miss(std::uint32_t steps) {
    RayHit h;
    h.steps = steps;
    return h;
}

}  // namespace

glm::ivec3 faceNormal(std::uint32_t face) {
    glm::ivec3 n(0);
    if (face < 6) n[face >> 1] = (face & 1) ? 1 : -1;
    return n;
}

RayHit traceRay(const BrickGrid& grid, const Ray& ray, TraversalMode mode) {
    const glm::vec3 o = ray.origin;
    const glm::vec3 d = ray.direction;
    const glm::ivec3 size = grid.sizeInVoxels();
    const bool hierarchical = mode == TraversalMode::Hierarchical;

    if (d == glm::vec3(0.0f)) return miss(0);

    // Clip the ray to the world box (slab test); an axis with d == 0 never bounds t. Such an
    // axis gets inv = +inf and counts as positive, so its exit distance below is always +inf.
    constexpr float kInf = std::numeric_limits<float>::infinity();
    const glm::bvec3 positive = glm::greaterThanEqual(d, glm::vec3(0.0f));
    glm::vec3 inv(kInf);
    float tEnter = 0.0f;
    float tExit = ray.tMax;
    int enterAxis = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0f) {
            if (o[a] < 0.0f || o[a] >= float(size[a])) return miss(0);
            continue;
        }
        inv[a] = 1.0f / d[a];
        float t0 = (0.0f - o[a]) * inv[a];
        float t1 = (float(size[a]) - o[a]) * inv[a];
        float tNear = std::min(t0, t1);
        float tFar = std::max(t0, t1);
        if (tNear > tEnter) {
            tEnter = tNear;
            enterAxis = a;
        }
        tExit = std::min(tExit, tFar);
    }
    if (tEnter > tExit) return miss(0);

    // p >= -epsilon here, so truncation equals floor after the clamp (and is cheaper).
    glm::ivec3 v = glm::clamp(glm::ivec3(o + tEnter * d), glm::ivec3(0), size - 1);
    std::uint32_t face = shared::FACE_INSIDE;
    if (enterAxis >= 0) {
        v[enterAxis] = positive[enterAxis] ? 0 : size[enterAxis] - 1;
        face = std::uint32_t(enterAxis * 2 + (positive[enterAxis] ? 0 : 1));
    }
    float t = tEnter;

    const std::span<const std::uint32_t> cells = grid.cells();
    const std::span<const std::uint32_t> supers = grid.superCells();
    for (std::uint32_t steps = 1; steps <= shared::TRAVERSAL_MAX_STEPS; ++steps) {
        int s = 1;
        std::uint32_t cell = 0;
        if (hierarchical && supers[grid.superCellIndex(v >> int(shared::SUPER_SHIFT))] == 0) {
            s = 32;
        } else if ((cell = cells[grid.cellIndex(v >> 3)]) == shared::CELL_EMPTY) {
            s = 8;
        } else if (cell & shared::CELL_HOMOGENEOUS) {
            return RayHit{true, v, face, t, static_cast<MaterialId>(cell & shared::CELL_MATERIAL_MASK), steps};
        } else {
            const std::uint32_t brick = BrickGrid::cellBrick(cell);
            const BrickMask& mask = grid.brickMask(brick);
            const glm::ivec3 local = v & 7;
            if (hierarchical && !mask.block4(local)) {
                s = 4;
            } else if (hierarchical && !mask.block2(local)) {
                s = 2;
            } else if (mask.voxel(local)) {
                return RayHit{true, v, face, t, grid.brickVoxels(brick)[brickVoxelIndex(local)], steps};
            }
        }

        // Leave the empty block of size s that contains v: the nearest exit plane (ties go to
        // the lowest axis), the exit axis stepped exactly, the others clamped into the block.
        const glm::ivec3 lo = v & ~(s - 1);
        const glm::vec3 boundary = glm::vec3(lo + glm::ivec3(positive) * s);
        const glm::vec3 ta = (boundary - o) * inv;
        const int axis = ta.x <= ta.y ? (ta.x <= ta.z ? 0 : 2) : (ta.y <= ta.z ? 1 : 2);
        const float best = ta[axis];
        if (best > ray.tMax) return miss(steps);
        v = glm::clamp(glm::ivec3(o + best * d), lo, lo + (s - 1));  // lo >= 0: truncation = floor
        v[axis] = positive[axis] ? lo[axis] + s : lo[axis] - 1;
        if (v[axis] < 0 || v[axis] >= size[axis]) return miss(steps);
        face = std::uint32_t(axis * 2 + (positive[axis] ? 0 : 1));
        t = best;
    }
    return miss(shared::TRAVERSAL_MAX_STEPS);
}

}  // namespace engine::world
