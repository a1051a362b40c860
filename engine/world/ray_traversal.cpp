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

    const std::span<const std::uint32_t> supers = grid.superCells();
    const glm::vec3 absInv = glm::abs(inv);
    glm::vec3 tNext(0.0f);   // where the ray leaves the current block, per axis
    glm::vec3 tDelta(0.0f);  // block size / |d|, per axis
    int level = 0;           // size of the block tNext belongs to (0: none yet)
    int exact = 1;           // v is exact down to blocks of this size; finer bits may lag
    // Brings v to the exact voxel the ray is in at t, inside the block it is known to be in.
    auto refine = [&] {
        const glm::ivec3 lo = v & ~(exact - 1);
        // lo >= 0: truncation = floor. The block may overhang the world; the ray at t does not.
        v = glm::clamp(glm::ivec3(o + t * d), lo, glm::min(lo + (exact - 1), size - 1));
        exact = 1;
    };
    for (std::uint32_t steps = 1; steps <= shared::TRAVERSAL_MAX_STEPS; ++steps) {
        int s = 1;
        // A non-zero skip distance: an empty super cell. The GPU walks runs of them in a tight
        // loop that reads the grid only where the distance runs out; the steps, and the
        // arithmetic of each, are these.
        if (hierarchical && supers[grid.superCellIndex(v >> int(shared::SUPER_SHIFT))] != 0) {
            s = 32;
        } else {
            if (exact > 8) refine();
            const std::uint32_t cell = grid.cell(v >> 3);
            if (cell == shared::CELL_EMPTY) {
                s = 8;
            } else if (cell & shared::CELL_HOMOGENEOUS) {
                if (exact > 1) refine();
                return RayHit{
                    true, v, face, t, static_cast<MaterialId>(cell & shared::CELL_MATERIAL_MASK),
                    steps};
            } else {
                const std::uint32_t brick = BrickGrid::cellBrick(cell);
                const BrickMask& mask = grid.brickMask(brick);
                if (exact > 4) refine();
                if (hierarchical && !mask.block4(v & 7)) {
                    s = 4;
                } else {
                    if (exact > 2) refine();
                    if (hierarchical && !mask.block2(v & 7)) {
                        s = 2;
                    } else {
                        if (exact > 1) refine();
                        if (mask.voxel(v & 7))
                            return RayHit{
                                true, v, face, t, grid.brickVoxels(brick)[brickVoxelIndex(v & 7)],
                                steps};
                    }
                }
            }
        }

        // Leave the empty block of size s around v: the nearest exit plane (ties go to the lowest
        // axis). Within one level the exits advance incrementally (Amanatides-Woo); a new level
        // restarts them from the ray origin, so errors do not accumulate across levels.
        const glm::ivec3 lo = v & ~(s - 1);
        if (s != level) {
            tNext = (glm::vec3(lo + glm::ivec3(positive) * s) - o) * inv;
            tDelta = float(s) * absInv;
            level = s;
        }
        const int axis =
            tNext.x <= tNext.y ? (tNext.x <= tNext.z ? 0 : 2) : (tNext.y <= tNext.z ? 1 : 2);
        const float best = tNext[axis];
        // tExit, not just tMax: a 32^3 super cell can reach past the world's edge, and the ray
        // must not walk on outside it (it would read cells of the next row).
        if (best > tExit) return miss(steps);
        v[axis] = positive[axis] ? lo[axis] + s : lo[axis] - 1;
        if (v[axis] < 0 || v[axis] >= size[axis]) return miss(steps);
        tNext[axis] += tDelta[axis];
        face = std::uint32_t(axis * 2 + (positive[axis] ? 0 : 1));
        t = best;
        exact = s;  // the other axes moved within the block: known only to its size
    }
    return miss(shared::TRAVERSAL_MAX_STEPS);
}

}  // namespace engine::world
