// What the injection's three dispatches share (shaders/vct/classify_texels.comp,
// list_dispatch.comp, inject_radiance.comp): their bindings, the texel list (shared/vct.h), where
// a texel of the clipmap lies, whether it keeps last frame's values, and the grid tests.
#ifndef VCT_INJECT_COMMON_GLSL
#define VCT_INJECT_COMMON_GLSL

#include "common/path_vertex.glsl"
#include "shared/vct.h"

layout(set = 0, binding = VCT_INJECT_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = VCT_INJECT_BINDING_PARAMS, std430) readonly buffer VctParamsBuffer { VctParams gVct; };
layout(set = 0, binding = VCT_INJECT_BINDING_PREVIOUS, std430) readonly buffer Previous { vec4 gPrevious[]; };
layout(set = 0, binding = VCT_INJECT_BINDING_VOLUME, std430) writeonly buffer Volume { vec4 gVolume[]; };
layout(set = 0, binding = VCT_INJECT_BINDING_LIST, std430) buffer List { uint gList[]; };
layout(set = 0, binding = VCT_INJECT_BINDING_BLOCKS, std430) readonly buffer Blocks { uint gBlocks[]; };

#define VCT_VOLUME gPrevious
#define VCT_ORIGIN(l) gVct.prevOrigin[l]
#include "vct/cone_trace.glsl"

uint vctLevels() { return clamp(gVct.levels, 1u, VCT_MAX_LEVELS); }

// One texel of the clipmap, from its index x + RES * (y + RES * (z + RES * level)).
struct VctInjectTexel {
    uint level;
    int size;          // voxels
    ivec3 minVoxel;    // its minimum corner
    ivec3 worldTexel;  // its world texel coordinate (the toroidal address's source)
    uint base;         // its first slot in the volume
};

VctInjectTexel vctInjectTexel(uint index) {
    VctInjectTexel t;
    t.level = index / VCT_TEXELS_PER_LEVEL;
    uvec3 c = uvec3(index % VCT_RES, (index / VCT_RES) % VCT_RES, (index / (VCT_RES * VCT_RES)) % VCT_RES);
    ivec4 o = gVct.levelOrigin[t.level];
    t.size = o.w;
    t.minVoxel = o.xyz + ivec3(c) * t.size;
    t.worldTexel = o.xyz / t.size + ivec3(c);
    t.base = vctTexelBase(t.level, t.worldTexel);
    return t;
}

// Last frame's values still hold (same place: toroidal addressing) unless the texel is new in
// the level, meets the dynamic objects, or its turn in the rotation has come; none hold when the
// world, the lights, the sky or the settings changed (VCT_PREVIOUS_VALID off).
bool vctKeepsPrevious(VctInjectTexel t) {
    if ((gVct.flags & VCT_PREVIOUS_VALID) == 0u) return false;
    ivec4 prev = gVct.prevOrigin[t.level];
    ivec3 inPrev = t.worldTexel - prev.xyz / t.size;
    bool wasIn = prev.w == t.size && all(greaterThanEqual(inPrev, ivec3(0))) && all(lessThan(inPrev, ivec3(int(VCT_RES))));
    bool dynamicNear = all(lessThan(t.minVoxel, gVct.dynamicMax.xyz)) && all(greaterThan(t.minVoxel + t.size, gVct.dynamicMin.xyz));
    uint turn = pcgHash(uint(t.worldTexel.x) ^ pcgHash(uint(t.worldTexel.y) ^ pcgHash(uint(t.worldTexel.z) ^ t.level)));
    bool due = (turn + gVct.frame) % max(gVct.refreshPeriod, 1u) == 0u;
    return wasIn && !dynamicNear && !due;
}

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

#endif
