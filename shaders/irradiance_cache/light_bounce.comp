#version 460
// Irradiance cache, light bounce (§4.6): each face gathers the light leaving its rays' selected
// hits — the direct light there from the sun and the emitter list (the sun and one emitter
// sample, one of them shadow-tested: directLightOneShadowRay; at a weighted subset of the hits:
// CacheParams::lightSamples), plus, with more than one bounce, the
// cached irradiance of the hit face — or the sky where a ray escapes. Cosine-distributed
// directions make E = pi * mean(L). The result is blended into the entry's running value.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"
#include "light_tiles/light_tiles.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;
layout(constant_id = FEATURE_CACHE_MULTI_BOUNCE) const bool kMultiBounce = true;  // off: one bounce, compiled out

// A selected hit that may receive direct light: a face of a voxel, reached from outside.
bool cacheHitLit(uint packed) { return packed != CACHE_HIT_MISS && cacheHitFace(packed) < 6u; }

// The hit as a surface for the light-sampling maths; valid = false where its voxel is empty (a
// dynamic voxel that moved away).
Surface cacheHitSurface(ivec3 voxel, vec3 o, vec3 d, uint packed, out ivec3 hv) {
    hv = cacheHitVoxel(voxel, packed, d);
    uint hf = cacheHitFace(packed);
    bool dynamicHit = (packed & CACHE_HIT_DYNAMIC) != 0u;
    uint material = dynamicHit ? dynamicVoxelMaterial(hv) : staticVoxelMaterial(hv);
    Surface s;
    s.face = hf;
    s.valid = material != 0u;
    s.position = o + d * faceHitT(o, d, hv, hf);
    s.normal = faceNormalF(hf);
    s.albedo = s.valid ? materialAlbedo(material) : vec3(0.0);
    s.emission = vec3(0.0);  // emitters are the direct-light passes' job
    return s;
}

// Light leaving a hit apart from its direct light: the sky where the ray escapes, and with more
// than one bounce the cached irradiance of the hit face.
vec3 indirectLeaving(ivec3 voxel, vec3 o, vec3 d, uint packed) {
    if (packed == CACHE_HIT_MISS) return skyBackground(gFrame, d);
    if (!(kMultiBounce && gCache.bounces > 1u) || !cacheHitLit(packed)) return vec3(0.0);
    ivec3 hv;
    Surface s = cacheHitSurface(voxel, o, d, packed, hv);
    if (!s.valid) return vec3(0.0);
    uint set = (packed & CACHE_HIT_DYNAMIC) != 0u ? CACHE_SET_DYNAMIC : CACHE_SET_STATIC;
    uint hs = cacheLookup(hv, set);
    ivec3 base;
    uint coarse = set == CACHE_SET_STATIC && hs == ~0u && gCache.lodDistance > 0.0 ? cacheCoarsePatch(hv, s.face, base) : 0u;
    if (coarse != 0u) hs = cacheLookupKey(base, set, coarse);  // a far face: its patch's coarse entry (cache_lod.h)
    if (hs == ~0u || (gEntries[hs].flags & CACHE_ENTRY_RESET) != 0u) return vec3(0.0);
    return s.albedo / PI * gFiltered[hs * CACHE_FACES + s.face].rgb * cacheFade(hs, set);
}

// The direct light leaving a hit: the sun and one emitter sample, one of them shadow-tested (a
// shadow ray per hit, not two: the pass's cost is its shadow rays).
vec3 directLeaving(ivec3 voxel, vec3 o, vec3 d, uint packed, inout uint rng) {
    ivec3 hv;
    Surface s = cacheHitSurface(voxel, o, d, packed, hv);
    return s.valid ? directLightOneShadowRay(s, gFrame, rng) : vec3(0.0);
}

void main() {
    uint S = gCache.raysPerUpdate;
    // One invocation per listed face (faces.comp): the static updates' list, then the dynamic one's.
    uint item, face;
    if (!cacheUpdateListedFace(cacheThread(), item, face)) return;
    uint slot = gLists[item];
    CacheEntry entry = gEntries[slot];
    ivec3 voxel = entry.voxel.xyz;
    uint index = slot * CACHE_FACES + face;
    uint rng = rngInit(uvec2(slot, face), gCache.frameIndex, 11u, gCache.seed);
    vec3 o = cacheEntryRayOrigin(entry, face);
    vec3 sum = vec3(0.0);
    uint rotation = cacheEntryRotation(entry);  // the directions its hits were traced along
    uint hits = (item * CACHE_FACES + face) * S;
    uint lit = 0u;  // hits that may receive direct light
    for (uint j = 0u; j < S; ++j) {
        uint packed = gSelectedHits[hits + j];
        sum += indirectLeaving(voxel, o, cacheDirection(rotation, face, cacheDirectionIndex(entry.phase, j)), packed);
        if (cacheHitLit(packed)) ++lit;
    }
    // Direct light at the lit hits: its shadow rays are the pass's cost, so with lightSamples > 0
    // only that many, stratified over the lit hits in order (one in each run of lit / samples, at
    // a random place in it), each weighted lit / samples: every lit hit is taken with probability
    // samples / lit, so the sum's expectation is unchanged. Every lane runs at most `samples`
    // iterations (lavapipe's batch of 8 pays for its slowest lane; a branch per hit would have
    // paid for the union of the lanes' choices).
    uint samples = gCache.lightSamples == 0u ? lit : min(gCache.lightSamples, lit);
    float weight = float(lit) / float(max(samples, 1u));
    float u = samples < lit ? rngNext(rng) : 0.0;
    uint j = 0u, rank = 0u;  // rank: lit hits before hit j
    for (uint k = 0u; k < samples; ++k) {
        uint target = samples < lit ? min(uint((float(k) + u) * weight), lit - 1u) : k;
        target = max(target, rank);  // strictly increasing (guards rounding)
        uint packed = gSelectedHits[hits + j];
        while ((!cacheHitLit(packed) || rank < target) && j + 1u < S) {
            if (cacheHitLit(packed)) ++rank;
            packed = gSelectedHits[hits + ++j];
        }
        if (!cacheHitLit(packed)) break;  // never: the lit hits are counted above
        vec3 d = cacheDirection(rotation, face, cacheDirectionIndex(entry.phase, j));
        sum += weight * directLeaving(voxel, o, d, packed, rng);
        ++rank;
        ++j;
    }
    vec3 fresh = PI * sum / float(S);
    // The running mean for the first 1/alpha updates, then the paper's exponential blend: a new
    // entry converges as fast as its samples allow and then keeps alpha's stability.
    vec4 old = (entry.flags & CACHE_ENTRY_RESET) != 0u ? vec4(0.0) : gIrradiance[index];
    float n = old.w + 1.0;
    float a = max(gCache.alpha, 1.0 / n);
    gIrradiance[index] = vec4(mix(old.rgb, fresh, a), n);
}
