#version 460
// Irradiance cache, this frame's face lists (see cacheListedFace in irradiance_cache.glsl): one
// invocation per face of every entry in the update and trace lists; faces with work are appended
// to their list, closed faces get their result here (irradiance 0, filtered and not). A closed
// face has no rays, so no pass reads its hits and none are written (on lavapipe every store loop
// here ran for every face); an edit that opens it makes its entry trace again. A list's order
// follows the atomics, which changes no result: each face's depends only on its entry and face.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;

void appendFace(uint list, uint item, uint face) {
    gLists[cacheListBase(list) + atomicAdd(gCounters[list], 1u)] = item * CACHE_FACES + face;
}

void main() {
    uint S = gCache.raysPerUpdate;
    uint thread = cacheThread();
    uint item = thread / CACHE_FACES;
    uint face = thread % CACHE_FACES;
    if (item < gCache.updates) {
        uint slot = gLists[item];
        CacheEntry entry = gEntries[slot];
        bool exposed = cacheEntryFaceExposed(entry, face);
        if (item < gCache.staticUpdates) {
            if (exposed) appendFace(CACHE_LIST_STATIC, item, face);
        } else if (exposed) {
            appendFace(CACHE_LIST_DYNAMIC, item, face);
        }
        if (!exposed) {
            // A dynamic entry's face may open (the object moves on) before its phase comes round
            // again, with no edit: its static hits are traced when it does (visibility_dynamic.comp).
            bool untraced = item >= gCache.staticUpdates && (entry.flags & CACHE_ENTRY_TRACE) != 0u;
            for (uint j = 0u; untraced && j < S; ++j)
                gStaticHits[(slot * CACHE_FACES + face) * gCache.directions + cacheDirectionIndex(entry.phase, j)] = CACHE_HIT_UNTRACED;
            gIrradiance[slot * CACHE_FACES + face] = vec4(0.0);
            gFiltered[slot * CACHE_FACES + face] = vec4(0.0);  // the filter runs over exposed faces
        }
    }
    if (item < gCache.traces) {
        uint slot = gLists[gCache.capacity + item];
        CacheEntry entry = gEntries[slot];
        if (cacheEntryFaceExposed(entry, face)) appendFace(CACHE_LIST_TRACE, item, face);
    }
}
