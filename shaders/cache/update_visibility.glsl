// Irradiance cache, visibility update (the paper's divide-and-win, §4.5): a static entry's ray
// keeps its cached static hit unless the dynamic grid, traced alone up to that hit, is nearer
// (the selection bit); a dynamic entry's ray traces static and dynamic worlds. The update list
// holds the static entries first; visibility_static.comp and visibility_dynamic.comp each run
// this over their part (VISIBILITY_SET), so each is timed on its own.
#include "common/irradiance_cache.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;

void main() {
    uint K = gCache.counts.z, S = gCache.counts.w;
    uint thread = cacheThread();
    uint staticEntries = gCache.image.z;
    uint item = thread / (CACHE_FACES * S);
    if (VISIBILITY_SET == CACHE_SET_DYNAMIC) item += staticEntries;
    if (item >= (VISIBILITY_SET == CACHE_SET_STATIC ? staticEntries : gCache.counts.x)) return;
    uint face = (thread / S) % CACHE_FACES;
    uint j = thread % S;
    uint slot = gLists[item];
    CacheEntry entry = gEntries[slot];
    ivec3 voxel = entry.voxel.xyz;
    uint set = uint(entry.voxel.w);
    uint selected = CACHE_HIT_MISS;
    if (cacheFaceExposed(voxel, face, set)) {
        uint k = cacheDirectionIndex(j);
        vec3 o = cacheRayOrigin(voxel, face);
        vec3 d = cacheDirection(face, k);
        float maxLength = gCache.blend.y;
        if (set == CACHE_SET_STATIC) {
            uint cached = gStaticHits[(slot * CACHE_FACES + face) * K + k];
            selected = cached;
            if ((gCache.table.z & CACHE_FLAG_FULL_RETRACE) != 0u) {
                // What the divide-and-win must equal: both worlds traced from scratch.
                SceneHit hit = traceScene(o, d, maxLength);
                selected = hit.hit ? packCacheHit(voxel, hit.voxel, hit.face, hit.dynamicSet) : CACHE_HIT_MISS;
            } else if (dynamicGridPresent()) {
                float ts = cached == CACHE_HIT_MISS ? maxLength
                                                    : faceHitT(o, d, cacheHitVoxel(voxel, cached), cacheHitFace(cached));
                SceneHit dyn = traceDynamic(o, d, ts);
                if (dyn.hit && faceHitT(o, d, dyn.voxel, dyn.face) < ts) selected = packCacheHit(voxel, dyn.voxel, dyn.face, true);
            }
        } else {
            SceneHit hit = traceScene(o, d, maxLength);
            if (hit.hit) selected = packCacheHit(voxel, hit.voxel, hit.face, hit.dynamicSet);
        }
    }
    gSelectedHits[(item * CACHE_FACES + face) * S + j] = selected;
}
