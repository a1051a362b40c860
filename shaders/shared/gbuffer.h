// G-buffer texel written by the primary-ray pass, one per pixel.
#ifndef SHARED_GBUFFER_H
#define SHARED_GBUFFER_H
#include "interop.h"

SHARED_BEGIN

struct GBufferTexel {
    ivec4 voxel;  // xyz hit voxel, w face (FACE_NONE where the ray left the world)
    uvec4 data;   // x material id, y floatBits(distance along the unit view ray), z DDA steps, w reserved
};
SHARED_ASSERT_SIZE(GBufferTexel, 32);

SHARED_END

#endif
