// Batch ray queries: one ray in, one hit out. Used by the GPU/CPU agreement tests and benchmarks.
#ifndef SHARED_TRACE_RAYS_H
#define SHARED_TRACE_RAYS_H
#include "interop.h"

SHARED_BEGIN

SHARED_CONST uint TRACE_MODE_HIERARCHICAL = 0u;
SHARED_CONST uint TRACE_MODE_PLAIN = 1u;
SHARED_CONST uint TRACE_MODE_SCENE = 2u;  // traceScene: static world + dynamic grid (scene_trace.glsl)

struct TraceRayInput {
    vec4 origin;     // xyz origin, w tMax
    vec4 direction;  // xyz direction (need not be unit), w unused
};
SHARED_ASSERT_SIZE(TraceRayInput, 32);

struct TraceRayOutput {
    ivec4 voxel;  // xyz hit voxel, w face
    uvec4 data;   // x hit (bit 0) and, in scene mode, dynamic set (bit 1), y material, z floatBits(t), w steps
};
SHARED_ASSERT_SIZE(TraceRayOutput, 32);

struct TraceRaysParams {
    uvec4 counts;  // x ray count, y mode (TRACE_MODE_*)
};
SHARED_ASSERT_SIZE(TraceRaysParams, 16);

SHARED_END

#endif
