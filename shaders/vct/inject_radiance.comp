#version 460
// Injects the radiance clipmap (shared/vct.h), one texel per invocation, every level: texels new
// in their level, near the dynamic objects or due in the rotation (one in refreshPeriod a frame)
// are injected, the others copied from last frame's volume; all of them when the world, the
// lights, the sky or the settings changed (VCT_PREVIOUS_VALID off). What is
// injected: the light the surfaces in the texel reflect from the sun and the emitters
// (common/direct_light.glsl's one-sample estimate, the one the cache and the path tracer use) —
// not their emission, which reaches the pixels as direct light. Per texel:
//  - coverage from the occupancy masks on a lattice of at most 4^3 blocks (voxels, 2^3 or 4^3
//    blocks, whichever the texel's size gives): per axis, the fraction of the texel's
//    cross-section some solid block covers (a one-voxel wall across the axis covers all of it);
//  - radiance per axis direction from one jittered ray crossing the texel along it (one ray, not
//    2x2, to keep the pass cheap on a CPU device): a ray travelling +x finds the surfaces
//    facing -x, the ones a cone travelling +x sees; a direction whose ray misses borrows the
//    texel's mean. The jitter is a hash of the texel's world position and the seed, not the
//    frame: a still scene injects the same values every frame (no flicker), and a texel's
//    values do not move with the camera. Each direction shades at most one surface point (one
//    sun and one emitter shadow ray).
// Without leak mitigation the texel is isotropic: the mean radiance of all its rays and the
// solid volume fraction as opacity in every slot.
#extension GL_GOOGLE_include_directive : require

#include "common/path_vertex.glsl"
#include "shared/vct.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = VCT_INJECT_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = VCT_INJECT_BINDING_PARAMS, std430) readonly buffer VctParamsBuffer { VctParams gVct; };
layout(set = 0, binding = VCT_INJECT_BINDING_PREVIOUS, std430) readonly buffer Previous { vec4 gPrevious[]; };
layout(set = 0, binding = VCT_INJECT_BINDING_VOLUME, std430) writeonly buffer Volume { vec4 gVolume[]; };

#define VCT_VOLUME gPrevious
#define VCT_ORIGIN(l) gVct.prevOrigin[l]
#include "vct/cone_trace.glsl"

const uint kRaysPerSide = 1u;  // rays per axis direction: kRaysPerSide^2

// Something solid in the b^3 block at world voxel v (b = 1, 2 or 4, v a multiple of b).
bool gridBlockSolid(bool dyn, ivec3 v, int b) {
    if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, gridSizeInVoxels(dyn)))) return false;
    uint cell = gridCell(dyn, v >> 3);
    if (cell == CELL_EMPTY) return false;
    if ((cell & CELL_HOMOGENEOUS) != 0u) return true;
    uint brick = cell - 1u;
    ivec3 l = v & 7;
    if (b >= 4) return ((gridMaskWord(dyn, brick, MASK_QUARTER_WORD) >> uint((l.x >> 2) + 2 * (l.y >> 2) + 4 * (l.z >> 2))) & 1u) != 0u;
    if (b == 2) {
        int bit = (l.x >> 1) + 4 * (l.y >> 1) + 16 * (l.z >> 1);
        return ((gridMaskWord(dyn, brick, MASK_COARSE_WORD + uint(bit >> 5)) >> uint(bit & 31)) & 1u) != 0u;
    }
    int bit = l.x + 8 * l.y + 64 * l.z;
    return ((gridMaskWord(dyn, brick, uint(bit >> 5)) >> uint(bit & 31)) & 1u) != 0u;
}

bool blockSolid(ivec3 v, int b) {
    if (gridBlockSolid(false, v, b)) return true;
    if (!dynamicGridPresent()) return false;
    // The dynamic grid's origin is brick-aligned, so the block stays aligned in it.
    loadDynamicGrid();
    return gridBlockSolid(true, v - gDynHeader.origin.xyz, b);
}

bool gridCellsOccupied(bool dyn, ivec3 minVoxel, int size) {
    ivec3 lo = max(minVoxel, ivec3(0)), hi = min(minVoxel + size, gridSizeInVoxels(dyn)) - 1;
    if (any(greaterThan(lo, hi))) return false;
    for (int z = lo.z >> 3; z <= hi.z >> 3; ++z)
        for (int y = lo.y >> 3; y <= hi.y >> 3; ++y)
            for (int x = lo.x >> 3; x <= hi.x >> 3; ++x)
                if (gridCell(dyn, ivec3(x, y, z)) != CELL_EMPTY) return true;
    return false;
}

bool anyCellOccupied(ivec3 minVoxel, int size) {
    if (gridCellsOccupied(false, minVoxel, size)) return true;
    if (!dynamicGridPresent()) return false;
    loadDynamicGrid();
    return gridCellsOccupied(true, minVoxel - gDynHeader.origin.xyz, size);
}

void main() {
    uint x = gl_GlobalInvocationID.x, yz = gl_GlobalInvocationID.y;
    uint levels = clamp(gVct.levels, 1u, VCT_MAX_LEVELS);
    if (x >= VCT_RES || yz >= VCT_RES * VCT_RES * levels) return;
    uint level = yz / (VCT_RES * VCT_RES);
    uvec3 c = uvec3(x, yz % VCT_RES, (yz / VCT_RES) % VCT_RES);
    ivec4 o = gVct.levelOrigin[level];
    int size = o.w;
    ivec3 minVoxel = o.xyz + ivec3(c) * size;
    ivec3 worldTexel = o.xyz / size + ivec3(c);
    uint base = vctTexelBase(level, worldTexel);

    // Keep last frame's values (same place: toroidal addressing) unless the texel is new in the
    // level, meets the dynamic objects, or its turn in the rotation has come.
    if ((gVct.flags & VCT_PREVIOUS_VALID) != 0u) {
        ivec4 prev = gVct.prevOrigin[level];
        ivec3 inPrev = worldTexel - prev.xyz / size;
        bool wasIn = prev.w == size && all(greaterThanEqual(inPrev, ivec3(0))) && all(lessThan(inPrev, ivec3(int(VCT_RES))));
        bool dynamicNear = all(lessThan(minVoxel, gVct.dynamicMax.xyz)) && all(greaterThan(minVoxel + size, gVct.dynamicMin.xyz));
        uint turn = pcgHash(uint(worldTexel.x) ^ pcgHash(uint(worldTexel.y) ^ pcgHash(uint(worldTexel.z) ^ level)));
        bool due = (turn + gVct.frame) % max(gVct.refreshPeriod, 1u) == 0u;
        if (wasIn && !dynamicNear && !due) {
            for (uint d = 0u; d < VCT_SLOTS; ++d) gVolume[base + d] = gPrevious[base + d];
            return;
        }
    }

    // Most texels are empty: their 8^3 cells first (one cell read for texels up to 8 voxels).
    if (!anyCellOccupied(minVoxel, size)) {
        for (uint d = 0u; d < VCT_SLOTS; ++d) gVolume[base + d] = vec4(0.0);
        return;
    }

    // Coverage: a lattice of n^3 blocks of b voxels.
    int n = min(size, 4), b = size / n;
    uint columnsX = 0u, columnsY = 0u, columnsZ = 0u, solid = 0u;
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                if (!blockSolid(minVoxel + ivec3(i, j, k) * b, b)) continue;
                ++solid;
                columnsX |= 1u << uint(j + n * k);
                columnsY |= 1u << uint(i + n * k);
                columnsZ |= 1u << uint(i + n * j);
            }
        }
    }
    if (solid == 0u) {
        for (uint d = 0u; d < VCT_SLOTS; ++d) gVolume[base + d] = vec4(0.0);
        return;
    }
    vec3 coverage = vec3(bitCount(columnsX), bitCount(columnsY), bitCount(columnsZ)) / float(n * n);
    float volumeFraction = float(solid) / float(n * n * n);

    // Radiance per direction. Seeded by the texel's world position (not the frame).
    uint rng = rngInit(uvec2(uint(minVoxel.x) ^ (level << 28u), uint(minVoxel.y)), uint(minVoxel.z), 80u, gVct.seed);
    const bool bounce = (gVct.flags & VCT_EXTRA_BOUNCE) != 0u && (gVct.flags & VCT_PREVIOUS_VALID) != 0u;
    const float eps = 1.0e-3;
    vec3 radiance[6];
    float hits[6];
    vec3 total = vec3(0.0);
    float totalHits = 0.0;
    for (uint d = 0u; d < VCT_SLOTS; ++d) {
        uint axis = d >> 1u;
        bool positive = (d & 1u) != 0u;
        vec3 dir = vec3(0.0);
        dir[axis] = positive ? 1.0 : -1.0;
        radiance[d] = vec3(0.0);
        hits[d] = 0.0;
        for (uint r = 0u; r < kRaysPerSide * kRaysPerSide; ++r) {
            vec2 cellUv = (vec2(r % kRaysPerSide, r / kRaysPerSide) + vec2(rngNext(rng), rngNext(rng))) / float(kRaysPerSide);
            vec3 origin = vec3(minVoxel);
            origin[(axis + 1u) % 3u] += cellUv.x * float(size);
            origin[(axis + 2u) % 3u] += cellUv.y * float(size);
            origin[axis] += positive ? -eps : float(size) + eps;
            SceneHit hit = traceScene(origin, dir, float(size) + 2.0 * eps);
            if (!hit.hit || hit.face >= 6u) continue;  // nothing, or the ray started inside a solid voxel
            Surface s = surfaceAt(hit, origin, dir);
            vec3 L = directLight(s, gFrame, rng);
            if (bounce) L += s.albedo * vctGather(s.position, s.normal, float(VCT_BASE_TEXEL) * gVct.startOffset, gFrame);
            radiance[d] += L;
            hits[d] += 1.0;
            break;
        }
        total += radiance[d];
        totalHits += hits[d];
    }
    vec3 mean = totalHits > 0.0 ? total / totalHits : vec3(0.0);
    const bool mitigate = (gVct.flags & VCT_LEAK_MITIGATION) != 0u;
    for (uint d = 0u; d < VCT_SLOTS; ++d) {
        if (!mitigate) {
            gVolume[base + d] = vec4(mean * volumeFraction, volumeFraction);
            continue;
        }
        // A direction whose rays all missed the solid part borrows the texel's mean.
        vec3 L = hits[d] > 0.0 ? radiance[d] / hits[d] : mean;
        float a = coverage[d >> 1u];
        gVolume[base + d] = vec4(L * a, a);
    }
}
