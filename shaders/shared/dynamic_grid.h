// The dynamic brick grid as the GPU sees it (engine/world/dynamic_grid.h, uploaded whole by
// render/gpu_dynamic_grid.h every frame it changes). One buffer, bound as world binding 4
// (WORLD_BINDING_DYNAMIC) and read through an R32_UINT texel view like the static grid's cells
// (a texel fetch is one gather for a SIMD batch on llvmpipe, a device-address read a loop over
// its lanes): DynamicGridHeader (DYNAMIC_HEADER_TEXELS words), then the super cells, top-grid
// cells, brick masks (BRICK_MASK_WORDS per brick), brick materials (BRICK_MATERIAL_WORDS per
// brick) and the object table (GpuDynamicObject per object) — each part at the texel offset the
// header gives, counted from the buffer's start; the super cells come first, at
// DYNAMIC_HEADER_TEXELS (shaders rely on that and on BrickGrid's size rules, common/world.glsl). BrickGridInfo::dynamicGrid.x says whether there
// is one. Cell encoding as in brick_grid.h; brick indices count from 0 in this buffer alone.
#ifndef SHARED_DYNAMIC_GRID_H
#define SHARED_DYNAMIC_GRID_H
#include "interop.h"

SHARED_BEGIN

struct DynamicGridHeader {
    ivec4 origin;            // xyz: world voxel of grid voxel (0,0,0) (brick-aligned), w: object count
    ivec4 sizeInCells;
    ivec4 sizeInVoxels;
    ivec4 sizeInSuperCells;
    uvec4 offsets;           // texel offsets: x super cells, y cells, z masks, w materials
    uvec4 objects;           // x: texel offset of the object table (a multiple of 4), yzw unused
};
SHARED_ASSERT_SIZE(DynamicGridHeader, 96);
SHARED_CONST uint DYNAMIC_HEADER_TEXELS = 24u;  // sizeof(DynamicGridHeader) / 4

// One object: where it is and how to take a point on it back to last frame, for motion vectors.
struct GpuDynamicObject {
    ivec4 boundsMin;      // xyz world voxels the object may cover (inclusive)
    ivec4 boundsMax;      // xyz (exclusive)
    mat4 prevFromCurrent; // previous worldFromModel * inverse(current worldFromModel)
};
SHARED_ASSERT_SIZE(GpuDynamicObject, 96);
SHARED_CONST uint DYNAMIC_OBJECT_TEXELS = 24u;  // sizeof(GpuDynamicObject) / 4

SHARED_END

#endif
