// Reservoir helpers for temporal and spatial reuse (Bitterli et al. 2020 Alg. 4 and 6; Lin et al. 2022).
#ifndef COMMON_RESERVOIR_GLSL
#define COMMON_RESERVOIR_GLSL

#include "common/surface.glsl"

Reservoir emptyReservoir() { return Reservoir(uvec4(RESERVOIR_EMPTY, 0u, 0u, 0u), vec4(0.0)); }

// A Reservoir from an R32G32B32A32_UINT view of a reservoir buffer, two texels per pixel: passes
// that only read a reservoir buffer fetch texels (see loadGBuffer in common/surface.glsl).
Reservoir loadReservoir(usamplerBuffer texels, uint i) {
    int t = int(i) * 2;
    return Reservoir(texelFetch(texels, t), uintBitsToFloat(texelFetch(texels, t + 1)));
}

bool reservoirHasLight(Reservoir r) { return r.light.x != RESERVOIR_EMPTY; }

// The reservoir as its own pixel reuses it: a sample the candidate pass found occluded here loses
// its weight (weights.w is that test's answer; 1 once applied or when untested).
Reservoir withOwnVisibility(Reservoir r) {
    r.weights.x *= r.weights.w;
    r.weights.w = 1.0;
    return r;
}

// A reservoir whose light was removed or replaced since it was chosen: its weight means nothing
// any more. (An empty reservoir is not stale: its M still records candidates that found no light,
// and dropping that would brighten the pixels where light is mostly occluded.)
bool reservoirStale(Reservoir r) { return reservoirHasLight(r) && !emitterCurrent(r.light.x, r.light.y); }

// Target pdf (luminance of the unshadowed contribution) of r's light sample at surface s; zero
// for a light that was removed or replaced since r chose it.
float targetAt(Surface s, Reservoir r) {
    if (!s.valid || !emitterCurrent(r.light.x, r.light.y)) return 0.0;
    vec3 toLight;
    float dist;
    return luminance(lightContribution(s, loadEmitter(r.light.x), r.light.z, unpackUnorm2x16(r.light.w), toLight, dist));
}

bool visibleAt(Surface s, Reservoir r) {
    GpuEmitter e = loadEmitter(r.light.x);
    vec3 toLight;
    float dist;
    vec3 f = lightContribution(s, e, r.light.z, unpackUnorm2x16(r.light.w), toLight, dist);
    return any(greaterThan(f, vec3(0.0))) && lightVisible(s, e, toLight, dist);
}

// Streaming combination of reservoirs at one pixel.
struct Combiner {
    Reservoir chosen;
    float wSum;
    float M;
    float chosenTarget;
};

Combiner combinerStart() { return Combiner(emptyReservoir(), 0.0, 0.0, 0.0); }

// Adds reservoir r whose light has target pdf `target` here; true when it was selected.
bool combinerAdd(inout Combiner c, Reservoir r, float target, float u) {
    float w = target * r.weights.x * r.weights.y;
    c.wSum += w;
    c.M += r.weights.y;
    if (w > 0.0 && u * c.wSum < w) {
        c.chosen = r;
        c.chosenTarget = target;
        return true;
    }
    return false;
}

// Adds reservoir r with an explicit MIS weight m(y) for its sample y (generalized RIS, Lin et al.
// 2022, "Generalized resampled importance sampling"): its resampling weight is
// m x target x W, and combinerFinish(c, 1.0) gives W = wSum / target. Unbiased when the weights of
// the inputs that can produce a sample sum to one wherever the integrand is not zero.
bool combinerAddWeighted(inout Combiner c, Reservoir r, float target, float m, float u) {
    float w = m * target * r.weights.x;
    c.wSum += w;
    c.M += r.weights.y;
    if (w > 0.0 && u * c.wSum < w) {
        c.chosen = r;
        c.chosenTarget = target;
        return true;
    }
    return false;
}

// The balance heuristic between two inputs a and b with confidences (their M): a's share of a
// sample whose target is targetA at a's pixel and targetB at b's; 0 when neither can produce it.
float balanceShare(float confidenceA, float targetA, float confidenceB, float targetB) {
    float a = confidenceA * targetA;
    float sum = a + confidenceB * targetB;
    return sum > 0.0 ? a / sum : 0.0;
}

// The combined reservoir: W = wSum / (normaliser x target), where the normaliser is the total M
// (the default mode), the M of the inputs that could have produced the chosen sample (Bitterli et
// al. 2020 Alg. 6), or 1 when the inputs were added with explicit MIS weights (the unbiased mode).
Reservoir combinerFinish(Combiner c, float normaliser) {
    Reservoir r = c.chosen;
    float W = (c.chosenTarget > 0.0 && normaliser > 0.0) ? c.wSum / (normaliser * c.chosenTarget) : 0.0;
    r.weights = vec4(W, c.M, c.chosenTarget, 1.0);
    return r;
}

#endif
