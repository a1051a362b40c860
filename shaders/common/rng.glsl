// Seeded per-invocation random numbers: the state is a hash of (pixel, frame, pass, seed), so a
// frame renders the same way every time. PCG hash as engine/core/hash.h.
#ifndef COMMON_RNG_GLSL
#define COMMON_RNG_GLSL

#include "common/hash.glsl"

uint rngInit(uvec2 pixel, uint frame, uint pass, uint seed) {
    return pcgHash(pixel.x ^ pcgHash(pixel.y ^ pcgHash(frame ^ pcgHash(pass ^ pcgHash(seed)))));
}

// Uniform in [0, 1).
float rngNext(inout uint state) {
    state = state * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    word = (word >> 22u) ^ word;
    return float(word >> 8u) * (1.0 / 16777216.0);
}

#endif
