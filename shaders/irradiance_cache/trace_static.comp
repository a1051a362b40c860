#version 460
// Irradiance cache, static set: an entry that is new or was invalidated by an edit traces the S
// directions of its current phase through the static world and keeps the hits for every later
// update (divide and win); after K / S such updates all K are cached. One invocation per face.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;

void main() {
    uint K = gCache.directions, S = gCache.raysPerUpdate;
    uint thread = cacheThread();
    uint item = thread / CACHE_FACES;
    if (item >= gCache.traces) return;
    uint face = thread % CACHE_FACES;
    uint slot = gLists[gCache.capacity + item];
    CacheEntry entry = gEntries[slot];
    ivec3 voxel = entry.voxel.xyz;
    bool exposed = cacheEntryFaceExposed(entry, face);
    uint rotation = cacheEntryRotation(entry);
    vec3 o = cacheEntryRayOrigin(entry, face);
    for (uint j = 0u; j < S; ++j) {
        uint k = cacheDirectionIndex(entry.phase, j);
        uint packed = CACHE_HIT_MISS;
        if (exposed) {
            vec3 d = cacheDirection(rotation, face, k);
            TraceResult hit = traceRay(o, d, gCache.maxRayLength, true);
            if (hit.hit) packed = packCacheHit(voxel, hit.voxel, hit.face, false, d);
        }
        gStaticHits[(slot * CACHE_FACES + face) * K + k] = packed;
    }
    if (exposed) atomicAdd(gCounters[CACHE_COUNTER_RAYS], S);
}
