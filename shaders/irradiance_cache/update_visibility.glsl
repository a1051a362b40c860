// Irradiance cache, visibility update (the paper's divide-and-win, §4.5): an entry's ray keeps
// its cached static hit unless the dynamic grid, traced alone up to that hit, is nearer (the
// selection bit). The update list holds the static entries first; visibility_static.comp and
// visibility_dynamic.comp each run this over their part (VISIBILITY_SET), so each is timed on its
// own. VISIBILITY_MODE picks the method at compile time — lavapipe runs both sides of a branch
// its lanes disagree on, and even a branch none takes costs, so the divide-and-win shader holds
// no full-trace code at all:
//   VISIBILITY_DIVIDE  cached static hit + the dynamic grid traced alone (static entries, whose
//                      hits trace_static.comp cached)
//   VISIBILITY_FULL    both worlds traced from scratch (the full-re-trace comparison mode)
//   VISIBILITY_REUSE   dynamic entries: the first update of a phase (CACHE_ENTRY_TRACE) traces the
//                      static world and caches the hit, later ones read it; then as DIVIDE. A
//                      dynamic key is a world voxel, so its static hits hold while it lives.
#define VISIBILITY_DIVIDE 0
#define VISIBILITY_FULL 1
#define VISIBILITY_REUSE 2
#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;

#if VISIBILITY_MODE == VISIBILITY_REUSE
// A dynamic entry's static hit along direction k of `face`: traced and kept on the first update
// of its phase, read from the cache on the later ones — unless an object's voxel covered the face
// at that first update (faces.comp marked it untraced): then traced and kept now.
uint reusedStaticHit(uint slot, ivec3 voxel, vec3 o, vec3 d, uint face, uint k, bool tracing) {
    uint at = (slot * CACHE_FACES + face) * gCache.directions + k;
    uint cached = tracing ? CACHE_HIT_UNTRACED : gStaticHits[at];
    if (cached != CACHE_HIT_UNTRACED) return cached;
    TraceResult s = traceRay(o, d, gCache.maxRayLength, true);
    uint packed = s.hit ? packCacheHit(voxel, s.voxel, s.face, false, d) : CACHE_HIT_MISS;
    gStaticHits[at] = packed;
    return packed;
}
#endif

// The selected hit of ray j of `face` of a static entry, or of a dynamic entry; `traced` counts
// the rays actually traced (divide and win traces none while no dynamic object exists).
uint selectHit(uint slot, ivec3 voxel, vec3 o, uint rotation, uint phase, uint face, uint j, bool tracing, inout uint traced) {
    uint K = gCache.directions;
    uint k = cacheDirectionIndex(phase, j);
    vec3 d = cacheDirection(rotation, face, k);
    float maxLength = gCache.maxRayLength;
#if !defined(VISIBILITY_MODE)
#error "define VISIBILITY_MODE"
#elif VISIBILITY_MODE == VISIBILITY_DIVIDE
    // Only static entries come here.
        uint cached = gStaticHits[(slot * CACHE_FACES + face) * K + k];
        if (!dynamicGridPresent()) return cached;
        float ts = cached == CACHE_HIT_MISS ? maxLength : faceHitT(o, d, cacheHitVoxel(voxel, cached, d), cacheHitFace(cached));
        ++traced;
        SceneHit dyn = traceDynamic(o, d, ts);
        if (dyn.hit && faceHitT(o, d, dyn.voxel, dyn.face) < ts) return packCacheHit(voxel, dyn.voxel, dyn.face, true, d);
        return cached;
#elif VISIBILITY_MODE == VISIBILITY_REUSE
    // traceScene's steps with the static part cached: the same hit, bit for bit (the packed hit
    // gives back the voxel and face, so ts is the same float).
    uint cached = reusedStaticHit(slot, voxel, o, d, face, k, tracing);
    ++traced;
    if (!dynamicGridPresent()) return cached;
    float ts = cached == CACHE_HIT_MISS ? maxLength : faceHitT(o, d, cacheHitVoxel(voxel, cached, d), cacheHitFace(cached));
    SceneHit dyn = traceDynamic(o, d, ts);
    if (dyn.hit && faceHitT(o, d, dyn.voxel, dyn.face) < ts) return packCacheHit(voxel, dyn.voxel, dyn.face, true, d);
    return cached;
#else
    // Dynamic entries, and what the divide-and-win must equal: both worlds traced from scratch.
    ++traced;
    SceneHit hit = traceScene(o, d, maxLength);
    return hit.hit ? packCacheHit(voxel, hit.voxel, hit.face, hit.dynamicSet, d) : CACHE_HIT_MISS;
#endif
}

// One invocation per exposed face of an entry (faces.comp; closed faces have no rays),
// looping over its S rays: the entry is read once, not per ray.
void main() {
    uint S = gCache.raysPerUpdate;
    uint item, face;
    if (!cacheListedFace(VISIBILITY_SET == CACHE_SET_STATIC ? CACHE_LIST_STATIC : CACHE_LIST_DYNAMIC, cacheThread(), item, face))
        return;
    uint slot = gLists[item];
    CacheEntry entry = gEntries[slot];
    ivec3 voxel = entry.voxel.xyz;
    uint rotation = cacheEntryRotation(entry);
    vec3 o = cacheEntryRayOrigin(entry, face);
    bool tracing = (entry.flags & CACHE_ENTRY_TRACE) != 0u;
    uint traced = 0u;
    for (uint j = 0u; j < S; ++j) {
        gSelectedHits[(item * CACHE_FACES + face) * S + j] =
            selectHit(slot, voxel, o, rotation, entry.phase, face, j, tracing, traced);
    }
    if (traced > 0u) atomicAdd(gCounters[CACHE_COUNTER_RAYS], traced);
}
