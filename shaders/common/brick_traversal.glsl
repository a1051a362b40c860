// Ray traversal of the two-level brick grid. Mirrors engine/world/ray_traversal.cpp operation for
// operation (`precise` here, -ffp-contract=off there) so both agree hit for hit; read that file
// for the method. Each step finds the coarsest empty block around the current voxel (32^3 super
// cell, 8^3 cell, 4^3, 2^3, voxel) and jumps to where the ray leaves it.
#ifndef COMMON_BRICK_TRAVERSAL_GLSL
#define COMMON_BRICK_TRAVERSAL_GLSL

#include "common/world.glsl"

struct TraceResult {
    bool hit;
    ivec3 voxel;
    uint face;
    float t;
    uint material;
    uint steps;
};

TraceResult traceMiss(uint steps) {
    return TraceResult(false, ivec3(0), FACE_NONE, 0.0, 0u, steps);
}

TraceResult traceRay(vec3 o, vec3 d, float tMax, bool hierarchical) {
    const ivec3 size = gWorld.sizeInVoxels.xyz;

    if (d == vec3(0.0)) return traceMiss(0u);

    const float kInf = uintBitsToFloat(0x7f800000u);
    const bvec3 positive = greaterThanEqual(d, vec3(0.0));
    precise vec3 inv = vec3(kInf);
    precise float tEnter = 0.0;
    precise float tExit = tMax;
    int enterAxis = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < 0.0 || o[a] >= float(size[a])) return traceMiss(0u);
            continue;
        }
        inv[a] = 1.0 / d[a];
        precise float t0 = (0.0 - o[a]) * inv[a];
        precise float t1 = (float(size[a]) - o[a]) * inv[a];
        float tNear = min(t0, t1);
        float tFar = max(t0, t1);
        if (tNear > tEnter) {
            tEnter = tNear;
            enterAxis = a;
        }
        tExit = min(tExit, tFar);
    }
    if (tEnter > tExit) return traceMiss(0u);

    precise vec3 p0 = o + tEnter * d;
    ivec3 v = clamp(ivec3(p0), ivec3(0), size - 1);  // p0 >= -epsilon: truncation = floor after the clamp
    uint face = FACE_INSIDE;
    if (enterAxis >= 0) {
        v[enterAxis] = positive[enterAxis] ? 0 : size[enterAxis] - 1;
        face = uint(enterAxis * 2 + (positive[enterAxis] ? 0 : 1));
    }
    precise float t = tEnter;

    for (uint steps = 1u; steps <= TRAVERSAL_MAX_STEPS; ++steps) {
        int s = 1;
        uint cell = 0u;
        if (hierarchical && worldSuperCell(v >> SUPER_SHIFT) == 0u) {
            s = 32;
        } else if ((cell = worldCell(v >> 3)) == CELL_EMPTY) {
            s = 8;
        } else if ((cell & CELL_HOMOGENEOUS) != 0u) {
            return TraceResult(true, v, face, t, cell & CELL_MATERIAL_MASK, steps);
        } else {
            uint brick = cell - 1u;
            BrickPage page = BrickPage(gPages[brick >> BRICK_PAGE_SHIFT]);
            uint maskBase = (brick & (BRICK_PAGE_BRICKS - 1u)) * BRICK_MASK_WORDS;
            ivec3 local = v & 7;
            ivec3 b4 = local >> 2;
            ivec3 b2 = local >> 1;
            int bit2 = b2.x + 4 * b2.y + 16 * b2.z;
            if (hierarchical && ((page.words[maskBase + MASK_QUARTER_WORD] >> uint(b4.x + 2 * b4.y + 4 * b4.z)) & 1u) == 0u) {
                s = 4;
            } else if (hierarchical &&
                       ((page.words[maskBase + MASK_COARSE_WORD + uint(bit2 >> 5)] >> uint(bit2 & 31)) & 1u) == 0u) {
                s = 2;
            } else {
                int bit = local.x + 8 * local.y + 64 * local.z;
                if (((page.words[maskBase + uint(bit >> 5)] >> uint(bit & 31)) & 1u) != 0u) {
                    return TraceResult(true, v, face, t, brickMaterial(brick, uint(bit)), steps);
                }
            }
        }

        // Leave the empty block of size s around v (see ray_traversal.cpp).
        ivec3 lo = v & ~(s - 1);
        precise vec3 boundary = vec3(lo + ivec3(positive) * s);
        precise vec3 ta = (boundary - o) * inv;
        int axis = ta.x <= ta.y ? (ta.x <= ta.z ? 0 : 2) : (ta.y <= ta.z ? 1 : 2);
        precise float best = ta[axis];
        if (best > tMax) return traceMiss(steps);
        precise vec3 p = o + best * d;
        v = clamp(ivec3(p), lo, lo + (s - 1));  // lo >= 0: truncation = floor
        v[axis] = positive[axis] ? lo[axis] + s : lo[axis] - 1;
        if (v[axis] < 0 || v[axis] >= size[axis]) return traceMiss(steps);
        face = uint(axis * 2 + (positive[axis] ? 0 : 1));
        t = best;
    }
    return traceMiss(TRAVERSAL_MAX_STEPS);
}

#endif
