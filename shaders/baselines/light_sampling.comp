#version 460
// Light-sampling baselines: N light samples per pixel, each with its own shadow ray (uniform or
// power-proportional emitter choice), or every light once ("brute force", for small scenes).
// More shadow rays than one dispatch's loop budget allows run as several dispatches over ranges
// of the emitters or samples (LightSamplingParams::first), the sum and the random state carried
// in the partial buffer: the same additions in the same order as one loop over all of them.
#extension GL_GOOGLE_include_directive : require

#include "common/camera.glsl"
#include "common/surface.glsl"
#include "shared/light_sampling.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = LIGHT_SAMPLING_BINDING_FRAME, std430) readonly buffer Params { FrameParams gFrame; };
layout(set = 0, binding = LIGHT_SAMPLING_BINDING_PARAMS, std430) readonly buffer Sampling { LightSamplingParams gSampling; };
layout(set = 0, binding = LIGHT_SAMPLING_BINDING_GBUFFER, std430) readonly buffer GBuffer { GBufferTexel gGBuffer[]; };
layout(set = 0, binding = LIGHT_SAMPLING_BINDING_RADIANCE, std430) writeonly buffer Radiance { vec4 gRadiance[]; };
layout(set = 0, binding = LIGHT_SAMPLING_BINDING_PARTIAL, std430) buffer Partial { uvec4 gPartial[]; };

// One sample of emitter `slot` chosen with probability `emitterProbability`: f V / p.
vec3 sampleEmitter(Surface s, uint slot, float emitterProbability, bool area, inout uint rng) {
    GpuEmitter e = loadEmitter(slot);
    uint face = LIGHT_FACE_CENTRE;
    vec2 uv = vec2(0.5);
    float pdf = emitterProbability;
    if (area) {
        float side = float(e.minCorner.w);
        pdf *= pickFace(e, s.position, rngNext(rng), face) / (side * side);
        uv = vec2(rngNext(rng), rngNext(rng));
    }
    if (!(pdf > 0.0)) return vec3(0.0);
    vec3 toLight;
    float dist;
    vec3 f = lightContribution(s, e, face, uv, toLight, dist);
    if (!any(greaterThan(f, vec3(0.0))) || !lightVisible(s, e, toLight, dist)) return vec3(0.0);
    return f / pdf;
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, gFrame.imageSize.xy))) return;
    uint index = pixel.x + pixel.y * gFrame.imageSize.x;
    bool firstPart = gSampling.first == 0u;
    bool lastPart = gSampling.end == LIGHT_SAMPLING_REST;
    GBufferTexel g = gGBuffer[index];
    Surface s = surfaceFrom(g);
    if (uint(g.voxel.w) == FACE_NONE) {
        if (lastPart) gRadiance[index] = vec4(skyBackground(gFrame, cameraRayDirection(gFrame, pixel)), 1.0);
        return;
    }
    if (!s.valid) {
        if (lastPart) gRadiance[index] = vec4(s.emission, 1.0);
        return;
    }
    bool area = gSampling.area != 0u;
    bool byPower = gSampling.byPower != 0u;
    uint n = gLights.counts.x;
    vec3 direct = vec3(0.0);
    uint rng;
    if (firstPart) {
        rng = rngInit(pixel, gSampling.frameIndex, 4u, gSampling.seed);
    } else {
        uvec4 partial = gPartial[index];
        direct = uintBitsToFloat(partial.xyz);
        rng = partial.w;
    }
    uint samples = max(gSampling.samples, 1u);
    if (gSampling.everyLight != 0u) {
        uint end = min(gSampling.end, n);
        for (uint i = gSampling.first; i < end; ++i) direct += sampleEmitter(s, gAlive[i], 1.0, area, rng);
    } else if (n > 0u) {
        uint end = min(gSampling.end, samples);
        for (uint i = gSampling.first; i < end; ++i) {
            uint slot;
            if (pickEmitter(rng, byPower, slot)) direct += sampleEmitter(s, slot, emitterPdf(slot, byPower), area, rng);
        }
        if (lastPart) direct /= float(samples);
    }
    if (!lastPart) {
        gPartial[index] = uvec4(floatBitsToUint(direct), rng);
        return;
    }
    vec3 radiance = s.emission;
    radiance += sunLight(s, gFrame);
    radiance += direct;
    gRadiance[index] = vec4(radiance, 1.0);
}
