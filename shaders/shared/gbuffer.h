// G-buffer texel written by the primary-ray pass, one per pixel.
#ifndef SHARED_GBUFFER_H
#define SHARED_GBUFFER_H
#include "interop.h"

SHARED_BEGIN

// data.w flags.
SHARED_CONST uint GBUFFER_FLAG_DYNAMIC = 1u;  // the hit voxel belongs to the dynamic grid (an object)

struct GBufferTexel {
    ivec4 voxel;     // xyz hit voxel (world coordinates, either set), w face (FACE_NONE where the ray left the world)
    uvec4 data;      // x material id, y floatBits(distance along the unit view ray), z DDA steps, w flags (GBUFFER_FLAG_*)
    vec4 position;   // xyz world-space hit point, w unused
    vec4 motion;     // xy: the same surface point's pixel position in the previous frame (pixel
                     // units, centre of pixel i at i + 0.5), z: its distance there, w: 1 if valid
};
SHARED_ASSERT_SIZE(GBufferTexel, 64);


SHARED_END

#endif
