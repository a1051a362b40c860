#version 460
// Irradiance cache, the rest of the final gather for the pixels cache.gather listed (no value at
// their own level): the other level, then the fallback (gather.glsl). Dispatched indirectly with
// the workgroups cache.gather counted, so only those pixels run this code.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/gather.glsl"

layout(local_size_x = CACHE_GATHER_LATE_GROUP_SIZE) in;

void main() {
    uint count = gCounters[CACHE_COUNTER_LATE_PIXELS];
    uint stride = gl_NumWorkGroups.x * CACHE_GATHER_LATE_GROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < count; i += stride) {
        uint index = gLatePixels[i];
        GatherPixel p = gatherPixel(index);
        gatherWrite(index, p, gatherRest(p));
    }
}
