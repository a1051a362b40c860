// The dynamic brick grid as the GPU sees it (engine/world/dynamic_grid.h, uploaded whole by
// render/gpu_dynamic_grid.h every frame it changes). One buffer, bound as world binding 4
// (WORLD_BINDING_DYNAMIC) and read through an R32_UINT texel view like the static grid's cells
// (a texel fetch is one gather for a SIMD batch on llvmpipe, a device-address read a loop over
// its lanes): DynamicGridHeader (DYNAMIC_HEADER_TEXELS words), then the super cells, top-grid
// cells, brick masks (BRICK_MASK_WORDS per brick), brick materials (BRICK_MATERIAL_WORDS per
// brick) and the object table (GpuDynamicObject per object) — each part at the texel offset the
// header gives, counted from the buffer's start; the header also holds the coarse occupancy
// (world/dynamic_grid.h's `occupancy`), which every ray tests before the dynamic traversal; the
// super cells come first, at DYNAMIC_HEADER_TEXELS (shaders rely on that and on BrickGrid's size
// rules, common/world.glsl). BrickGridInfo::dynamicGrid.x says whether there is one. Cell encoding
// as in brick_grid.h; brick indices count from 0 in this buffer alone.
#ifndef SHARED_DYNAMIC_GRID_H
#define SHARED_DYNAMIC_GRID_H
#include "interop.h"

SHARED_BEGIN

// Boxes of the coarse occupancy: a ray that nears none of them skips the dynamic traversal.
SHARED_CONST uint DYNAMIC_OCCUPANCY_BOXES = 4u;

struct DynamicGridHeader {
    ivec4 origin;  // xyz: world voxel of grid voxel (0,0,0) (brick-aligned), w: object count
    ivec4 sizeInCells;
    ivec4 sizeInVoxels;
    ivec4 sizeInSuperCells;
    uvec4 offsets;  // texel offsets: x super cells, y cells, z masks, w materials
    uvec4 objects;  // x: texel offset of the object table (a multiple of 4), y: occupancy boxes in
                    // use
    // The coarse occupancy: boxes of whole cells (world voxels, max exclusive) that together hold
    // every voxel of the grid; the first objects.y are in use.
    ivec4 occupiedMin[DYNAMIC_OCCUPANCY_BOXES];
    ivec4 occupiedMax[DYNAMIC_OCCUPANCY_BOXES];
};
SHARED_ASSERT_SIZE(DynamicGridHeader, 224);
SHARED_CONST uint DYNAMIC_HEADER_TEXELS = 56u;        // sizeof(DynamicGridHeader) / 4
SHARED_CONST uint DYNAMIC_HEADER_OCCUPIED_MIN = 24u;  // texel of occupiedMin[0]; box i at + 4i
SHARED_CONST uint DYNAMIC_HEADER_OCCUPIED_MAX = 40u;  // texel of occupiedMax[0]

// One object: where it is and how to take a point on it back to last frame, for motion vectors.
struct GpuDynamicObject {
    ivec4 boundsMin;       // xyz world voxels the object may cover (inclusive)
    ivec4 boundsMax;       // xyz (exclusive)
    mat4 prevFromCurrent;  // previous worldFromModel * inverse(current worldFromModel)
};
SHARED_ASSERT_SIZE(GpuDynamicObject, 96);
SHARED_CONST uint DYNAMIC_OBJECT_TEXELS = 24u;  // sizeof(GpuDynamicObject) / 4

// Whether the segment o + t d, 0 <= t <= tMax, comes within one voxel of the box [lo, hi)
// (world voxels): a slab test on the box grown by one voxel, so rounding never drops a ray whose
// traversal would find a voxel in the box. An axis with d == 0 bounds nothing but the origin; a
// NaN (a denormal direction) never rejects. The CPU's traceDynamic and the shaders' run this same
// code, so both skip the same rays and count the same steps.
#ifdef __cplusplus
inline bool segmentNearsBox(glm::vec3 o, glm::vec3 d, float tMax, glm::ivec3 lo, glm::ivec3 hi) {
#else
bool segmentNearsBox(vec3 o, vec3 d, float tMax, ivec3 lo, ivec3 hi) {
#endif
    float tEnter = float(0);
    float tExit = tMax;
    for (int a = 0; a < 3; ++a) {
        float low = float(lo[a] - 1), high = float(hi[a] + 1);
        if (d[a] == float(0)) {
            if (o[a] < low || o[a] > high) return false;
            continue;
        }
        float inv = float(1) / d[a];
        float t0 = (low - o[a]) * inv;
        float t1 = (high - o[a]) * inv;
        float tNear = t0 < t1 ? t0 : t1;
        float tFar = t0 < t1 ? t1 : t0;
        if (tNear > tEnter) tEnter = tNear;
        if (tFar < tExit) tExit = tFar;
    }
    return !(tEnter > tExit);
}

SHARED_END

#endif
