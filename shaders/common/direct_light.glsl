// One-sample estimate of the direct light at a diffuse surface: the sun (one shadow ray) plus one
// emitter drawn by power, area-sampled, with one shadow ray. Shared by the reference path tracer
// and the irradiance cache's light bounce, so both see the same lights the same way.
#ifndef COMMON_DIRECT_LIGHT_GLSL
#define COMMON_DIRECT_LIGHT_GLSL

#include "common/surface.glsl"

vec3 directLight(Surface s, FrameParams frame, inout uint rng) {
    vec3 direct = sunLight(s, frame);
    uint slot;
    if (!pickEmitter(rng, true, slot)) return direct;
    GpuEmitter e = gEmitters[slot];
    uint face;
    float side = float(e.minCorner.w);
    float pdf = emitterPdf(slot, true) * pickFace(e, s.position, rngNext(rng), face) / (side * side);
    vec2 uv = vec2(rngNext(rng), rngNext(rng));
    if (!(pdf > 0.0)) return direct;
    vec3 toLight;
    float dist;
    vec3 f = lightContribution(s, e, face, uv, toLight, dist);
    if (any(greaterThan(f, vec3(0.0))) && lightVisible(s, e, toLight, dist)) direct += f / pdf;
    return direct;
}

#endif
