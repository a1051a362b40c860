#version 460
// Reference path tracer: progressive, over the same grid and lights as every other method.
// Pixel filter: a box over the pixel — each sample traces its own camera ray through a uniformly
// jittered point of the pixel's square (seeded, so the same inputs give the same image), through
// the static world and the dynamic objects (traceScene, as the G-buffer does). The G-buffer is
// not read: one ray through the pixel centre aliases at every edge. (REFERENCE_PIXEL_CENTRE traces
// through the pixel centre, for comparisons with the methods that shade the G-buffer.)
// From the surface hit on, the walk of common/path_vertex.glsl: at each vertex, next-event
// estimation of the emitters (by power, area sampling, one shadow ray) and of the sun, and a
// cosine-weighted ray that counts the emission of the light it hits (also from the last vertex,
// where it goes no further); the two ways of reaching an emitter are combined by multiple
// importance sampling (power heuristic, Veach & Guibas 1995), so a light close to a surface no
// longer makes fireflies. Continuation rays that escape see the sky; Russian roulette after three
// bounces. With zero bounces it is the direct-light ground truth, by light sampling alone as before.
#extension GL_GOOGLE_include_directive : require

#include "common/camera.glsl"
#include "common/path_vertex.glsl"
#include "shared/reference.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = REFERENCE_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = REFERENCE_BINDING_PARAMS, std430) readonly buffer Reference { ReferenceParams gReference; };
layout(set = 0, binding = REFERENCE_BINDING_ACCUMULATION, std430) buffer Accumulation { vec4 gAccum[]; };
layout(set = 0, binding = REFERENCE_BINDING_RADIANCE, std430) writeonly buffer Radiance { vec4 gRadiance[]; };

// Test probe: the emitter derived for the static voxel seen through the pixel centre.
vec4 probeEmitter(uvec2 pixel, uint flags) {
    SceneHit hit = traceScene(gFrame.cameraPosition.xyz, cameraRayDirection(gFrame, pixel), 1.0e30);
    EmitterShape shape;
    if (!hit.hit || hit.dynamicSet || !emitterOfStaticVoxel(hit.voxel, (flags & REFERENCE_BRICK_LIGHTS) != 0u, shape)) {
        return vec4(-1.0);
    }
    if ((flags & REFERENCE_PROBE_EMITTER_SHAPE) != 0u) {
        return vec4(vec3(shape.emitter.minCorner.xyz), float(shape.emitter.info.x | (uint(shape.emitter.minCorner.w) << 6u)));
    }
    return vec4(shape.power, shape.power / gLights.power.x, 0.0, 0.0);
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    uint flags = gReference.flags;
    if ((flags & (REFERENCE_PROBE_EMITTER_SHAPE | REFERENCE_PROBE_EMITTER_POWER)) != 0u) {
        gRadiance[index] = probeEmitter(pixel, flags);
        return;
    }
    uint bounces = gReference.bounces;
    // The direct-light reference (no bounces) stays light sampling alone: the ground truth the
    // quadrature test checks, at its old cost.
    const bool mis = (flags & REFERENCE_LIGHT_SAMPLING_ONLY) == 0u && bounces > 0u;
    const bool brickLights = (flags & REFERENCE_BRICK_LIGHTS) != 0u;
    vec4 accum = gAccum[index];
    uint spp = max(gReference.samples, 1u);
    for (uint sampleIndex = 0u; sampleIndex < spp; ++sampleIndex) {
        uint rng = rngInit(pixel, uint(accum.w), 5u, gReference.seed);
        // Box filter: a uniform point of the pixel (or its centre, on request).
        vec2 jitter = vec2(0.5);
        if ((flags & REFERENCE_PIXEL_CENTRE) == 0u) jitter = vec2(rngNext(rng), rngNext(rng));
        vec3 origin = gFrame.cameraPosition.xyz;
        vec3 dir = cameraRayDirectionAt(gFrame, vec2(pixel) + jitter);
        SceneHit hit = traceScene(origin, dir, 1.0e30);
        vec3 L;
        if (!hit.hit) {
            L = skyBackground(gFrame, dir);
        } else {
            Surface s = surfaceAt(hit, origin, dir);
            L = s.emission;
            addPathRadiance(L, s, vec3(1.0), 0u, bounces, mis, brickLights, gFrame, rng);
        }
        accum += vec4(L, 1.0);
    }
    gAccum[index] = accum;
    gRadiance[index] = vec4(accum.rgb / accum.w, 1.0);
}
