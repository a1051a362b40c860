#version 460
// Irradiance cache, final gather (§4.8): a pixel reads the face its normal points along from its
// set's entries (static pixels the static set only: dynamic objects never leak into static
// surfaces), bilinearly across the neighbouring voxels in the face's plane. Neighbours without a
// value drop out and the weights renormalise: the padding of §4.7 without storing padded voxels.
// Adds albedo/pi * E to the frame's radiance. Far static faces read coarse entries (2x2 patches)
// the same way, between patch centres. A pixel that finds no value at its level is listed for
// cache.gather_late (gather_late.comp), which tries the other level and falls back to the nearest
// entries of its plane on the same side (gather.glsl).
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/gather.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, uvec2(gCache.width, gCache.height)))) return;
    uint index = pixel.x + pixel.y * gCache.width;
    GatherPixel p = gatherPixel(index);
    vec4 r = vec4(0.0);
    if (p.face < 6u) r = gatherFirst(p);
    if (p.face < 6u && r.w == 0.0) {
        // Listed for the late pass, which writes its indirect term. Its workgroups, as the
        // indirect dispatch's arguments: enough for every listed pixel, at most 65535 (its
        // invocations stride over the list).
        uint i = atomicAdd(gCounters[CACHE_COUNTER_LATE_PIXELS], 1u);
        gLatePixels[i] = index;
        atomicMax(gCounters[CACHE_COUNTER_LATE_GROUPS], min(i / CACHE_GATHER_LATE_GROUP_SIZE + 1u, 65535u));
        gCounters[CACHE_COUNTER_LATE_GROUPS + 1u] = 1u;
        gCounters[CACHE_COUNTER_LATE_GROUPS + 2u] = 1u;
        return;
    }
    gatherWrite(index, p, r);
}
