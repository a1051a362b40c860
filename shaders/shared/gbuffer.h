// G-buffer texel written by the primary-ray pass, one per pixel.
#ifndef SHARED_GBUFFER_H
#define SHARED_GBUFFER_H
#include "interop.h"

SHARED_BEGIN

struct GBufferTexel {
    ivec4 voxel;     // xyz hit voxel, w face (FACE_NONE where the ray left the world)
    uvec4 data;      // x material id, y floatBits(distance along the unit view ray), z DDA steps, w flags
    vec4 position;   // xyz world-space hit point, w unused
    vec4 motion;     // xy: the same surface point's pixel position in the previous frame (pixel
                     // units, centre of pixel i at i + 0.5), z: its distance there, w: 1 if valid
};
SHARED_ASSERT_SIZE(GBufferTexel, 64);

SHARED_CONST uint GBUFFER_FLAG_DYNAMIC = 1u;  // data.w: the voxel belongs to the dynamic set

SHARED_END

#endif
