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

    precise vec3 inv = vec3(0.0);
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

    ivec3 v;
    for (int a = 0; a < 3; ++a) {
        precise float p = o[a] + tEnter * d[a];
        v[a] = clamp(int(floor(p)), 0, size[a] - 1);
    }
    uint face = FACE_INSIDE;
    if (enterAxis >= 0) {
        bool positive = d[enterAxis] > 0.0;
        v[enterAxis] = positive ? 0 : size[enterAxis] - 1;
        face = uint(enterAxis * 2 + (positive ? 0 : 1));
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
            ivec3 local = v & 7;
            ivec3 b4 = local >> 2;
            ivec3 b2 = local >> 1;
            uint quarter = brickMaskWord(brick, MASK_QUARTER_WORD) >> uint(b4.x + 2 * b4.y + 4 * b4.z);
            int bit2 = b2.x + 4 * b2.y + 16 * b2.z;
            if (hierarchical && (quarter & 1u) == 0u) {
                s = 4;
            } else if (hierarchical &&
                       ((brickMaskWord(brick, MASK_COARSE_WORD + uint(bit2 >> 5)) >> uint(bit2 & 31)) & 1u) == 0u) {
                s = 2;
            } else {
                int bit = local.x + 8 * local.y + 64 * local.z;
                if (((brickMaskWord(brick, uint(bit >> 5)) >> uint(bit & 31)) & 1u) != 0u) {
                    return TraceResult(true, v, face, t, brickMaterial(brick, uint(bit)), steps);
                }
            }
        }

        ivec3 lo = v & ~(s - 1);
        precise float best = 1.0 / 0.0;
        int axis = 0;
        for (int a = 0; a < 3; ++a) {
            if (d[a] == 0.0) continue;
            int boundary = d[a] > 0.0 ? lo[a] + s : lo[a];
            precise float ta = (float(boundary) - o[a]) * inv[a];
            if (ta < best) {
                best = ta;
                axis = a;
            }
        }
        if (best > tMax) return traceMiss(steps);
        for (int b = 0; b < 3; ++b) {
            if (b == axis) continue;
            precise float p = o[b] + best * d[b];
            v[b] = clamp(int(floor(p)), lo[b], lo[b] + s - 1);
        }
        bool positive = d[axis] > 0.0;
        v[axis] = positive ? lo[axis] + s : lo[axis] - 1;
        if (v[axis] < 0 || v[axis] >= size[axis]) return traceMiss(steps);
        face = uint(axis * 2 + (positive ? 0 : 1));
        t = best;
    }
    return traceMiss(TRAVERSAL_MAX_STEPS);
}

#endif
