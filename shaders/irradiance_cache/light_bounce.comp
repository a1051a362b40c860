#version 460
// Irradiance cache, light bounce (§4.6): each face gathers the light leaving its rays' selected
// hits — the direct light there from the sun and the emitter list (sampled, with shadow rays),
// plus, with more than one bounce, the cached irradiance of the hit face — or the sky where a ray
// escapes. Cosine-distributed directions make E = pi * mean(L). The result is blended into the
// entry's running value.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"
#include "light_tiles/light_tiles.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;
layout(constant_id = FEATURE_CACHE_MULTI_BOUNCE) const bool kMultiBounce = true;  // off: one bounce, compiled out

vec3 lightLeaving(ivec3 voxel, uint face, vec3 o, vec3 d, uint packed, inout uint rng) {
    if (packed == CACHE_HIT_MISS) return skyBackground(gFrame, d);
    ivec3 hv = cacheHitVoxel(voxel, packed, d);
    uint hf = cacheHitFace(packed);
    bool dynamicHit = (packed & CACHE_HIT_DYNAMIC) != 0u;
    if (hf >= 6u) return vec3(0.0);  // the ray started inside a voxel: no light
    uint material = dynamicHit ? dynamicVoxelMaterial(hv) : staticVoxelMaterial(hv);
    if (material == 0u) return vec3(0.0);
    Surface s;
    s.face = hf;
    s.valid = true;
    s.position = o + d * faceHitT(o, d, hv, hf);
    s.normal = faceNormalF(hf);
    s.albedo = gMaterials[material].albedo.rgb;
    s.emission = vec3(0.0);  // emitters are the direct-light passes' job
    vec3 L = directLightFromTiles(s, gFrame, rng);
    if (kMultiBounce && gCache.bounces > 1u) {
        uint hs = cacheLookup(hv, dynamicHit ? CACHE_SET_DYNAMIC : CACHE_SET_STATIC);
        if (hs != ~0u && (gEntries[hs].flags & CACHE_ENTRY_RESET) == 0u) L += s.albedo / PI * gFiltered[hs * CACHE_FACES + hf].rgb * cacheFade(hs);
    }
    return L;
}

void main() {
    uint S = gCache.raysPerUpdate;
    // One invocation per listed face (faces.comp): the static updates' list, then the dynamic one's.
    uint thread = cacheThread(), item, face;
    uint staticFaces = gCounters[CACHE_LIST_STATIC];
    if (!(thread < staticFaces ? cacheListedFace(CACHE_LIST_STATIC, thread, item, face)
                               : cacheListedFace(CACHE_LIST_DYNAMIC, thread - staticFaces, item, face))) return;
    uint slot = gLists[item];
    CacheEntry entry = gEntries[slot];
    ivec3 voxel = entry.voxel.xyz;
    uint index = slot * CACHE_FACES + face;
    uint rng = rngInit(uvec2(slot, face), gCache.frameIndex, 11u, gCache.seed);
    vec3 o = cacheEntryRayOrigin(entry, face);
    vec3 sum = vec3(0.0);
    uint rotation = cacheEntryRotation(entry);  // the directions its hits were traced along
    for (uint j = 0u; j < S; ++j) {
        vec3 d = cacheDirection(rotation, face, cacheDirectionIndex(entry.phase, j));
        sum += lightLeaving(voxel, face, o, d, gSelectedHits[(item * CACHE_FACES + face) * S + j], rng);
    }
    vec3 fresh = PI * sum / float(S);
    // The running mean for the first 1/alpha updates, then the paper's exponential blend: a new
    // entry converges as fast as its samples allow and then keeps alpha's stability.
    vec4 old = (entry.flags & CACHE_ENTRY_RESET) != 0u ? vec4(0.0) : gIrradiance[index];
    float n = old.w + 1.0;
    float a = max(gCache.alpha, 1.0 / n);
    gIrradiance[index] = vec4(mix(old.rgb, fresh, a), n);
}
