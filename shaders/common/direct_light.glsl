// One-sample estimate of the direct light at a diffuse surface: the sun (one shadow ray) plus one
// emitter drawn by power, area-sampled, with one shadow ray. Shared by the reference path tracer
// and the irradiance cache's light bounce, so both see the same lights the same way.
#ifndef COMMON_DIRECT_LIGHT_GLSL
#define COMMON_DIRECT_LIGHT_GLSL

#include "common/surface.glsl"

// Power heuristic (Veach & Guibas 1995, beta = 2): the weight of a sample drawn with density
// `chosen` when `other` could also have produced it.
float powerHeuristic(float chosen, float other) {
    if (!(chosen > 0.0)) return 0.0;
    float ratio = other / chosen;  // as a ratio: a grazing light sample's huge density cannot overflow
    return 1.0 / (1.0 + ratio * ratio);
}

// A sample of emitter e, drawn with probability `chosen`, for surface s: a face by solid angle and
// a uniform point on it (`face`). f is its unshadowed contribution, pdf its density (area
// measure), and (toLight, dist) its shadow ray; false when the sample cannot light s.
bool sampleEmitter(Surface s, GpuEmitter e, float chosen, inout uint rng, out vec3 f, out float pdf, out uint face,
                   out vec3 toLight, out float dist) {
    f = vec3(0.0);
    toLight = vec3(0.0, 0.0, 1.0);
    dist = 0.0;
    float side = float(e.minCorner.w);
    pdf = chosen * pickFace(e, s.position, rngNext(rng), face) / (side * side);
    vec2 uv = vec2(rngNext(rng), rngNext(rng));
    if (!(pdf > 0.0)) return false;
    f = lightContribution(s, e, face, uv, toLight, dist);
    return any(greaterThan(f, vec3(0.0)));
}

// With `misWithCosine`, the emitter sample is weighted against cosine-weighted BSDF sampling, for
// a vertex that also traces a cosine-sampled ray counting the emission it hits (the reference
// path tracer with MIS). The sun stays light-sampled only: a direction has zero chance of hitting
// it. Either way the same random numbers are drawn.
vec3 directLightSampled(Surface s, FrameParams frame, inout uint rng, bool misWithCosine) {
    vec3 direct = sunLight(s, frame);
    uint slot;
    if (!pickEmitter(rng, true, slot)) return direct;
    GpuEmitter e = loadEmitter(slot);
    vec3 f, toLight;
    float pdf, dist;
    uint face;
    if (!sampleEmitter(s, e, emitterPdf(slot, true), rng, f, pdf, face, toLight, dist) || !lightVisible(s, e, toLight, dist))
        return direct;
    float weight = 1.0;
    if (misWithCosine) {
        float cosLight = dot(faceNormalF(face), -toLight);
        float lightPdf = pdf * dist * dist / cosLight;  // area -> solid angle at s
        float bsdfPdf = max(dot(s.normal, toLight), 0.0) / PI;
        weight = powerHeuristic(lightPdf, bsdfPdf);
    }
    return direct + f / pdf * weight;
}

vec3 directLight(Surface s, FrameParams frame, inout uint rng) { return directLightSampled(s, frame, rng, false); }

vec3 directLightMis(Surface s, FrameParams frame, inout uint rng) { return directLightSampled(s, frame, rng, true); }

#endif
