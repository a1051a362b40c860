#version 460
// Path-traced indirect light from the G-buffer's surface: per pixel, `samples` cosine-sampled
// bounce rays, each continued by the reference path tracer's walk (common/path_vertex.glsl) from
// the surface it hits, i.e. vertex 1 on: the light the direct methods leave out. The emission the
// first bounce ray finds is left out too — it is direct light, the direct method's. So the mean
// is the reference's (bounces) minus its (direct only) at the pixel centre. Averaged over frames
// in a running sum while the camera and the world stay still; PATH_INDIRECT_RESTART drops it.
// Writes the term alone and adds it to the frame's radiance, as the irradiance cache's gather does.
#extension GL_GOOGLE_include_directive : require

#include "common/path_vertex.glsl"
#include "shared/path_indirect.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = PATH_INDIRECT_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = PATH_INDIRECT_BINDING_PARAMS, std430) readonly buffer PathParams { PathIndirectParams gPath; };
layout(set = 0, binding = PATH_INDIRECT_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = PATH_INDIRECT_BINDING_ACCUMULATION, std430) buffer Accumulation { vec4 gAccum[]; };
layout(set = 0, binding = PATH_INDIRECT_BINDING_INDIRECT, std430) writeonly buffer Indirect { vec4 gIndirect[]; };
layout(set = 0, binding = PATH_INDIRECT_BINDING_RADIANCE, std430) buffer Radiance { vec4 gRadiance[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    const uint flags = gPath.flags;
    const bool brickLights = (flags & PATH_INDIRECT_BRICK_LIGHTS) != 0u;
    vec4 accum = (flags & PATH_INDIRECT_RESTART) != 0u ? vec4(0.0) : gAccum[index];
    Surface s = surfaceFrom(gGBuffer[index]);
    uint samples = max(gPath.samples, 1u);
    for (uint i = 0u; i < samples; ++i) {
        vec3 L = vec3(0.0);
        if (s.valid) {
            // Stream 64 + i: one per path, apart from every other pass's (1-11).
            uint rng = rngInit(pixel, gPath.frame, 64u + gPath.firstSample + i, gPath.seed);
            vec3 dir = cosineDirection(s.normal, rngNext(rng), rngNext(rng));
            vec3 origin = s.position + s.normal * kRayOffset;
            SceneHit hit = traceScene(origin, dir, 1.0e30);
            if (!hit.hit) {
                L = s.albedo * skyBackground(gFrame, dir);
            } else {
                addPathRadiance(L, surfaceAt(hit, origin, dir), s.albedo, 1u, gPath.bounces, true, brickLights, gFrame, rng);
            }
        }
        accum += vec4(L, 1.0);
    }
    gAccum[index] = accum;
    if ((flags & PATH_INDIRECT_FINAL) == 0u) return;
    vec3 indirect = accum.rgb / accum.w;
    gIndirect[index] = vec4(indirect, 1.0);
    gRadiance[index] += vec4(indirect, 0.0);
}
