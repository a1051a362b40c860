#version 460
// Irradiance cache, static set: an entry that is new or was invalidated by an edit traces the S
// directions of its current phase through the static world and keeps the hits for every later
// update (divide and win); after K / S such updates all K are cached. One invocation per exposed
// face (faces.comp wrote the closed ones' misses).
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;

void main() {
    uint K = gCache.directions, S = gCache.raysPerUpdate;
    uint item, face;
    if (!cacheListedFace(CACHE_LIST_TRACE, cacheThread(), item, face)) return;
    uint slot = gLists[gCache.capacity + item];
    CacheEntry entry = gEntries[slot];
    ivec3 voxel = entry.voxel.xyz;
    uint rotation = cacheEntryRotation(entry);
    vec3 o = cacheEntryRayOrigin(entry, face);
    for (uint j = 0u; j < S; ++j) {
        uint k = cacheDirectionIndex(entry.phase, j);
        vec3 d = cacheDirection(rotation, face, k);
        TraceResult hit = traceRay(o, d, gCache.maxRayLength, true);
        gStaticHits[(slot * CACHE_FACES + face) * K + k] = hit.hit ? packCacheHit(voxel, hit.voxel, hit.face, false, d) : CACHE_HIT_MISS;
    }
    atomicAdd(gCounters[CACHE_COUNTER_RAYS], S);
}
