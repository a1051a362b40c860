#version 460
// Batch ray queries for tests and benchmarks: TraceRayInput in, TraceRayOutput out.
#extension GL_GOOGLE_include_directive : require

#include "common/scene_trace.glsl"
#include "shared/trace_rays.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = PASS_BINDING_FIRST + 0, std430) readonly buffer Params { TraceRaysParams gParams; };
layout(set = 0, binding = PASS_BINDING_FIRST + 1, std430) readonly buffer Rays { TraceRayInput gRays[]; };
layout(set = 0, binding = PASS_BINDING_FIRST + 2, std430) writeonly buffer Hits { TraceRayOutput gHits[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= gParams.counts.x) return;
    TraceRayInput ray = gRays[i];
    TraceRayOutput out_;
    if (gParams.counts.y == TRACE_MODE_SCENE) {
        SceneHit h = traceScene(ray.origin.xyz, ray.direction.xyz, ray.origin.w);
        out_.voxel = ivec4(h.voxel, int(h.face));
        out_.data = uvec4((h.hit ? 1u : 0u) | (h.dynamicSet ? 2u : 0u), h.material, floatBitsToUint(h.t), h.steps);
    } else {
        TraceResult r = traceRay(ray.origin.xyz, ray.direction.xyz, ray.origin.w, gParams.counts.y == TRACE_MODE_HIERARCHICAL);
        out_.voxel = ivec4(r.voxel, int(r.face));
        out_.data = uvec4(r.hit ? 1u : 0u, r.material, floatBitsToUint(r.t), r.steps);
    }
    gHits[i] = out_;
}
