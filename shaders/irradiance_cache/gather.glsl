// Irradiance cache, final gather (§4.8), shared by its two passes: cache.gather reads every
// pixel's entries at its level (gatherPixel, gatherLevel) and sets aside the few pixels that find
// no value there; cache.gather_late finishes those (gatherRest: the other level, then the
// fallback). On llvmpipe a batch of 8 lanes runs all the code its shader holds, taken or not, so
// the rare paths cost every pixel while they live in the same pass; in a pass of their own they
// cost only the pixels that take them. Same operations per pixel either way: the same image.
#ifndef IRRADIANCE_CACHE_GATHER_GLSL
#define IRRADIANCE_CACHE_GATHER_GLSL

#include "irradiance_cache/irradiance_cache.glsl"

// Bilinear over the entries around point `p` of the face's plane: voxels' entries (coarse = 0)
// at voxel centres, or coarse entries at 2x2 patch centres. Returns the weighted sum, weights in w.
vec4 gatherLevel(ivec3 voxel, uint face, uint set, vec3 p, uint coarse) {
    uint axis = face >> 1u, ua = (axis + 1u) % 3u, va = (axis + 2u) % 3u;
    float cell = coarse != 0u ? 2.0 : 1.0;
    vec2 uv = vec2(p[ua], p[va]) / cell - 0.5;
    ivec2 base = ivec2(floor(uv));
    vec2 f = uv - vec2(base);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int j = 0; j <= 1; ++j) {
        for (int i = 0; i <= 1; ++i) {
            ivec3 v = voxel;
            v[ua] = (base.x + i) * int(cell);
            v[va] = (base.y + j) * int(cell);
            uint slot = cacheLookupKey(v, set, coarse);
            if (slot == ~0u) continue;
            vec4 e = gFiltered[slot * CACHE_FACES + face];
            if (e.w == 0.0) continue;
            float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) + 1e-6;
            sum += w * e.rgb * cacheFade(slot, set);
            weights += w;
        }
    }
    return vec4(sum, weights);
}

// A pixel whose voxel and its bilinear neighbours have no value yet — seen for the first time
// (its entry comes a frame late) or waiting for the ray budget — reads the nearest square ring of
// entries around it in the face's plane, up to gCache.fallbackRadius voxels away, whose entries
// have the same face and whose front is reachable through the open space in front of the pixel's
// (cacheFrontsConnected: never across a wall), weighted by inverse squared distance. The rings
// step over voxels' entries (step 1, `coarse` 0) or, for a far pixel in an open patch, over the
// coarse entries of its plane's patches (step 2 from the patch's base). It runs in
// cache.gather_late, over only the pixels that need it; pixels that find nothing search every
// ring. `fallback` 0 compiles it out (shared/shader_features.h).
layout(constant_id = FEATURE_CACHE_FALLBACK) const bool kFallback = true;
vec4 gatherFallback(ivec3 voxel, uint face, uint set, vec3 p, ivec3 origin, int step, uint coarse) {
    uint axis = face >> 1u, ua = (axis + 1u) % 3u, va = (axis + 2u) % 3u;
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    int radius = (int(gCache.fallbackRadius) + step - 1) / step;
    for (int ring = 1; weights == 0.0 && ring <= radius; ++ring) {
        for (int j = -ring; j <= ring; ++j) {
            // The whole row at the ring's top and bottom, its two ends in between.
            for (int i = -ring; i <= ring; i += abs(j) == ring ? 1 : 2 * ring) {
                ivec3 v = origin;
                v[ua] += step * i;
                v[va] += step * j;
                uint slot = cacheLookupKey(v, set, coarse);
                if (slot == ~0u) continue;
                vec4 e = gFiltered[slot * CACHE_FACES + face];
                ivec2 offset = ivec2(v[ua] - voxel[ua], v[va] - voxel[va]);
                if (e.w == 0.0 || !cacheFrontsConnected(voxel, face, offset, set)) continue;
                vec2 d = vec2(v[ua], v[va]) + 0.5 * float(step) - vec2(p[ua], p[va]);
                float w = 1.0 / max(dot(d, d), 0.25);
                sum += w * e.rgb * cacheFade(slot, set);
                weights += w;
            }
        }
    }
    return vec4(sum, weights);
}

// What a pixel's gather needs from its G-buffer texel, and its level: far static faces read
// their open patch's coarse entries (cache_lod.h; `coarse` from cacheCoarsePatch, with its patch's
// base voxel). The host chose the keys from the previous frame's pixels, so where this frame's
// level has no entry yet the other level (if the patch is open) stands in (gatherRest).
struct GatherPixel {
    GBufferTexel g;
    uint face;  // FACE_NONE etc. for the sky
    uint set;
    bool lod;   // static face with level of detail on
    bool far;
    uint coarse;
    ivec3 patchBase;
};

GatherPixel gatherPixel(uint index) {
    GatherPixel p;
    p.g = loadGBuffer(gGBuffer, index);
    p.face = uint(p.g.voxel.w);
    p.set = (p.g.data.w & GBUFFER_FLAG_DYNAMIC) != 0u ? CACHE_SET_DYNAMIC : CACHE_SET_STATIC;
    p.lod = p.set == CACHE_SET_STATIC && gCache.lodDistance > 0.0;
    p.far = uintBitsToFloat(p.g.data.y) >= gCache.lodDistance;
    p.coarse = 0u;
    p.patchBase = ivec3(0);
    if (p.face < 6u && p.lod && p.far) p.coarse = cacheCoarsePatch(p.g.voxel.xyz, p.face, p.patchBase);
    return p;
}

// The pixel's own level.
vec4 gatherFirst(GatherPixel p) {
    return gatherLevel(p.g.voxel.xyz, p.face, p.set, p.g.position.xyz, p.far ? p.coarse : 0u);
}

// After gatherFirst found nothing: the other level, then the fallback. A near pixel asks whether
// its patch is open (eight voxel reads) only here.
vec4 gatherRest(GatherPixel p) {
    vec4 r = vec4(0.0);
    uint coarse = p.coarse;
    ivec3 patchBase = p.patchBase;
    if (p.lod && !p.far) coarse = cacheCoarsePatch(p.g.voxel.xyz, p.face, patchBase);
    if (coarse != 0u) r = gatherLevel(p.g.voxel.xyz, p.face, p.set, p.g.position.xyz, p.far ? 0u : coarse);
    if (kFallback && r.w == 0.0) r = gatherFallback(p.g.voxel.xyz, p.face, p.set, p.g.position.xyz, p.g.voxel.xyz, 1, 0u);
    if (kFallback && r.w == 0.0 && coarse != 0u)
        r = gatherFallback(p.g.voxel.xyz, p.face, p.set, p.g.position.xyz, patchBase, 2, coarse);
    return r;
}

// Adds albedo/pi * E (r: weighted sum, weights in w; none: 0) to the pixel's radiance.
void gatherWrite(uint index, GatherPixel p, vec4 r) {
    vec3 indirect = vec3(0.0);
    if (r.w > 0.0) indirect = materialAlbedo(p.g.data.x) / PI * (r.rgb / r.w);
    gIndirect[index] = vec4(indirect, 1.0);
    gRadiance[index] += vec4(indirect, 0.0);
}

#endif
