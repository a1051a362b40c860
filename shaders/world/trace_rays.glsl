// Batch ray queries for tests and benchmarks: TraceRayInput in, TraceRayOutput out. One shader per
// mode (TRACE_MODE, set by trace_rays_*.comp): llvmpipe runs SIMD lanes under masks and pays for
// code in branches its lanes never take, so a run-time mode switch would slow every mode down.
#extension GL_GOOGLE_include_directive : require

#include "common/scene_trace.glsl"
#include "shared/trace_rays.h"

#if !defined(TRACE_MODE)
#error "define TRACE_MODE"
#endif

layout(local_size_x = 64) in;

layout(set = 0, binding = TRACE_BINDING_PARAMS, std430) readonly buffer Params { TraceRaysParams gParams; };
layout(set = 0, binding = TRACE_BINDING_RAYS, std430) readonly buffer Rays { TraceRayInput gRays[]; };
layout(set = 0, binding = TRACE_BINDING_HITS, std430) writeonly buffer Hits { TraceRayOutput gHits[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= gParams.counts.x) return;
    TraceRayInput ray = gRays[i];
    TraceRayOutput out_;
    if (TRACE_MODE == TRACE_MODE_SCENE) {  // a constant: the compiler keeps one side
        SceneHit h = traceScene(ray.origin.xyz, ray.direction.xyz, ray.origin.w);
        out_.voxel = ivec4(h.voxel, int(h.face));
        out_.data = uvec4((h.hit ? 1u : 0u) | (h.dynamicSet ? 2u : 0u), h.material, floatBitsToUint(h.t), h.steps);
    } else {
        TraceResult r = traceRay(ray.origin.xyz, ray.direction.xyz, ray.origin.w, TRACE_MODE == TRACE_MODE_HIERARCHICAL);
        out_.voxel = ivec4(r.voxel, int(r.face));
        out_.data = uvec4(r.hit ? 1u : 0u, r.material, floatBitsToUint(r.t), r.steps);
    }
    gHits[i] = out_;
}
