// Ray traversal of the two-level brick grid. Mirrors engine/world/ray_traversal.cpp operation for
// operation (`precise` here, -ffp-contract=off there) so both agree hit for hit; read that file
// for the method. Each step finds the coarsest empty block around the current voxel (32^3 super
// cell, 8^3 cell, 4^3, 2^3, voxel) and jumps to where the ray leaves it. In runs of empty super
// cells the super grid is read only where the last read's skip distance runs out. One loop, one
// step per pass, as on the CPU: on llvmpipe a nested open-air loop cost every finer step a pass.
// traceGrid walks either the static world or the dynamic grid (grid-local coordinates); its
// `dyn` flag is a constant at each call, so the compiler folds it away after inlining and the
// static walk's arithmetic is the one the CPU reference agrees with bit for bit.
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

// The exact voxel the ray is in at t, inside the block of size `exact` that holds v.
ivec3 refineVoxel(ivec3 v, int exact, vec3 o, vec3 d, float t, ivec3 size) {
    ivec3 lo = v & ~(exact - 1);
    precise vec3 p = o + t * d;
    // lo >= 0: truncation = floor. The block may overhang the world; the ray at t does not.
    return clamp(ivec3(p), lo, min(lo + (exact - 1), size - 1));
}

// One DDA step out of the block [lo, lo + s) around v: to the nearest exit plane (ties go to the
// lowest axis, as in ray_traversal.cpp), with the same arithmetic per component. Written with
// per-component selects rather than a run-time axis index into the vectors, the form llvmpipe's
// SIMD code takes anyway. False when the ray passes tExit or leaves the world.
bool leaveBlock(inout ivec3 v, inout vec3 tNext, vec3 tDelta, ivec3 lo, int s, bvec3 positive, ivec3 size,
                float tExit, out float best, out uint face) {
    bool xFirst = tNext.x <= tNext.y && tNext.x <= tNext.z;
    bool yFirst = !(tNext.x <= tNext.y) && tNext.y <= tNext.z;
    bvec3 axis = bvec3(xFirst, yFirst, !xFirst && !yFirst);
    best = xFirst ? tNext.x : (yFirst ? tNext.y : tNext.z);
    v = mix(v, mix(lo - 1, lo + s, positive), axis);
    int c = xFirst ? v.x : (yFirst ? v.y : v.z);
    int n = xFirst ? size.x : (yFirst ? size.y : size.z);
    bool pos = xFirst ? positive.x : (yFirst ? positive.y : positive.z);
    tNext = mix(tNext, tNext + tDelta, axis);
    face = (xFirst ? 0u : (yFirst ? 2u : 4u)) + (pos ? 0u : 1u);
    return !(best > tExit || c < 0 || c >= n);
}

// With dyn, the caller has called loadDynamicGrid (traceDynamic, which needs the origin first).
TraceResult traceGrid(vec3 o, vec3 d, float tMax, bool hierarchical, bool dyn) {
    const ivec3 size = gridSizeInVoxels(dyn);

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

    const vec3 absInv = abs(inv);
    // Grid sizes are read once, here: llvmpipe compiles a buffer read into a loop over the SIMD
    // lanes with a branch per lane (Mesa 21.3's source does so even for an address all lanes
    // share) and runs both sides of every branch under a lane mask, so a step pays for every read
    // its code holds, whichever level its lanes are on. The loop holds four: a super cell, a cell
    // and two mask words, all texel fetches of one view, which llvmpipe gathers without a branch
    // per lane (it held eleven storage and device-address reads). See docs/PERFORMANCE.md.
    const ivec3 superSize = gridSizeInSuperCells(dyn);
    const ivec3 cellSize = gridSizeInCells(dyn);
    const uint superBase = superCellBase(cellSize);
    const uint masksBase = dyn ? 0u : maskBase();
    const uint pagesBase = dyn ? 0u : pageBaseOf(cellSize, 0u);
    precise vec3 tNext = vec3(0.0);
    precise vec3 tDelta = vec3(0.0);
    int level = 0;
    int exact = 1;
    // One exit, at the loop's head: llvmpipe runs a SIMD batch's lanes in lockstep, and every
    // `return` inside the loop would add masked bookkeeping to every step of every lane.
    bool hit = false;
    bool done = false;
    uint material = 0u;
    uint hitBrick = 0u;  // a brick voxel's material is read once, after the loop
    int hitBit = -1;
    uint steps = 0u;
    // What the last reads found, and where: a lane reads again only when it has left the box its
    // last super-grid read vouches for, or moved to another cell, brick slab or mask word.
    // llvmpipe still runs each read's code for the batch, but skips the memory access for every
    // lane that does not need it.
    ivec3 boxCentre = ivec3(-1);  // super cell of the last super-grid read (its skip distance in `skip`)
    uint skip = 0u;
    // The static world's top-grid page of boxCentre's region, from the same read (an occupied
    // super cell names it): the cell reads below need no region-table read.
    uint page = 0u;
    ivec3 cellKey = ivec3(-1);    // cell of `cell`
    uint cell = CELL_EMPTY;
    uint masks = 0u;              // index of the first mask word of the brick in `cell`
    int coarseKey = -1;           // index of the 2^3-block mask word in `coarse`
    uint coarse = 0u;
    int fineKey = -1;             // index of the voxel mask word in `fine`
    uint fine = 0u;
    while (!done && steps < TRAVERSAL_MAX_STEPS) {
        ++steps;
        int s = 1;
        bool air = false;
        if (hierarchical) {
            // Open air: the super cell is empty. The grid is read again only when v leaves the
            // box the last read's skip distance says is empty (skip 0: that super cell alone).
            ivec3 superCell = v >> SUPER_SHIFT;
            ivec3 off = abs(superCell - boxCentre);
            if (uint(max(off.x, max(off.y, off.z))) >= max(skip, 1u)) {
                boxCentre = superCell;
                uint superWord = gridSuperCellIn(dyn, superSize, superBase, superCell);
                skip = superWord & SUPER_SKIP_MASK;
                page = superWord >> SUPER_PAGE_SHIFT;
            }
            air = skip != 0u;
        }
        if (air) {
            s = 32;
        } else {
            // Below super-cell level every test wants the exact voxel: refine once, here (the
            // CPU refines lazily per level; both give the same v at every test that reads it).
            if (exact > 1) {
                v = refineVoxel(v, exact, o, d, t, size);
                exact = 1;
            }
            bool newCell = any(notEqual(v >> 3, cellKey));
            if (newCell) {
                cellKey = v >> 3;
                if (dyn) {
                    cell = gridCellIn(dyn, cellSize, cellKey);
                } else if (hierarchical) {
                    cell = pageCell(pagesBase + page * PAGE_CELLS, cellKey);
                } else {
                    cell = pageCell(cellPageBase(cellSize, cellKey), cellKey);  // no super-grid read
                }
                coarseKey = -1;
                fineKey = -1;
                if (cell != CELL_EMPTY && (cell & CELL_HOMOGENEOUS) == 0u) {
                    masks = gridBrickMaskIndex(dyn, masksBase, cell - 1u);
                }
            }
            if (cell == CELL_EMPTY) {
                s = 8;
            } else if ((cell & CELL_HOMOGENEOUS) != 0u) {
                hit = true;
                material = cell & CELL_MATERIAL_MASK;
            } else {
                uint brick = cell - 1u;
                ivec3 local = v & 7;
                ivec3 b4 = local >> 2;
                ivec3 b2 = local >> 1;
                int bit2 = b2.x + 4 * b2.y + 16 * b2.z;
                int bit = local.x + 8 * local.y + 64 * local.z;
                if (hierarchical) {
                    // One word of the 2^3-block mask answers both coarse tests: it holds the
                    // 4-voxel-high slab of v (bit2 >> 5 == b4.z), and a 4^3 block is empty exactly
                    // when its eight 2^3 blocks are (bits 0,1,4,5,16,17,20,21 from its corner) —
                    // the same answer as the CPU's 4^3-block mask, whose bits are those ORs.
                    if (coarseKey != (bit2 >> 5)) {
                        coarseKey = bit2 >> 5;
                        coarse = gridMaskWordAt(dyn, masks + MASK_COARSE_WORD + uint(coarseKey));
                    }
                    if ((coarse & (0x330033u << uint(2 * b4.x + 8 * b4.y))) == 0u) {
                        s = 4;
                    } else if (((coarse >> uint(bit2 & 31)) & 1u) == 0u) {
                        s = 2;
                    }
                }
                if (s == 1 && fineKey != (bit >> 5)) {
                    fineKey = bit >> 5;
                    fine = gridMaskWordAt(dyn, masks + uint(fineKey));
                }
                if (s == 1 && ((fine >> uint(bit & 31)) & 1u) != 0u) {
                    hit = true;
                    hitBrick = brick;
                    hitBit = bit;
                }
            }
        }
        if (hit) {
            done = true;
        } else {
            // Leave the empty block of size s around v (see ray_traversal.cpp).
            ivec3 lo = v & ~(s - 1);
            if (s != level) {
                tNext = (vec3(lo + ivec3(positive) * s) - o) * inv;
                tDelta = float(s) * absInv;
                level = s;
            }
            float best;
            // Past tMax or out of the world: a miss (see ray_traversal.cpp).
            done = !leaveBlock(v, tNext, tDelta, lo, s, positive, size, tExit, best, face);
            t = best;
            exact = s;
        }
    }
    if (!hit) return traceMiss(steps);
    if (hitBit >= 0) material = gridBrickMaterial(dyn, hitBrick, uint(hitBit));
    return TraceResult(true, v, face, t, material, steps);
}

// The static world (the traversal tests call this directly; rays use traceScene).
TraceResult traceRay(vec3 o, vec3 d, float tMax, bool hierarchical) {
    return traceGrid(o, d, tMax, hierarchical, false);
}

#endif
