#version 460
// Irradiance cache, static set: traces each new (or invalidated) entry's K rays per exposed face
// through the static world once and keeps the hit (voxel and face) for every later update.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;

void main() {
    uint K = gCache.directions;
    uint thread = cacheThread();
    uint item = thread / (CACHE_FACES * K);
    if (item >= gCache.traces) return;
    uint face = (thread / K) % CACHE_FACES;
    uint k = thread % K;
    uint slot = gLists[gCache.capacity + item];
    ivec3 voxel = gEntries[slot].voxel.xyz;
    uint packed = CACHE_HIT_MISS;
    if (cacheFaceExposed(voxel, face, CACHE_SET_STATIC)) {
        vec3 d = cacheDirection(cacheRotation(voxel, CACHE_SET_STATIC), face, k);
        TraceResult hit = traceRay(cacheRayOrigin(voxel, face), d, gCache.maxRayLength, true);
        if (hit.hit) packed = packCacheHit(voxel, hit.voxel, hit.face, false, d);
    }
    gStaticHits[(slot * CACHE_FACES + face) * K + k] = packed;
}
