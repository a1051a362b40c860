#version 460
// Irradiance cache, final gather (§4.8): a pixel reads the face its normal points along from its
// set's entries (static pixels the static set only: dynamic objects never leak into static
// surfaces), bilinearly across the neighbouring voxels in the face's plane. Neighbours without a
// value drop out and the weights renormalise: the padding of §4.7 without storing padded voxels.
// Adds albedo/pi * E to the frame's radiance. Far static faces read coarse entries (2x2 patches)
// the same way, between patch centres. A pixel left without a value falls back to the nearest
// entries of its plane on the same side (gatherFallback).
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

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
// coarse entries of its plane's patches (step 2 from the patch's base). A loop that no lane enters
// costs nothing on lavapipe, so a view whose pixels all have entries pays little; pixels that find
// nothing search every ring. `fallback` 0 compiles it out (shared/shader_features.h).
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

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, uvec2(gCache.width, gCache.height)))) return;
    uint index = pixel.x + pixel.y * gCache.width;
    GBufferTexel g = loadGBuffer(gGBuffer, index);
    uint face = uint(g.voxel.w);
    vec3 indirect = vec3(0.0);
    if (face < 6u) {
        uint set = (g.data.w & GBUFFER_FLAG_DYNAMIC) != 0u ? CACHE_SET_DYNAMIC : CACHE_SET_STATIC;
        // Level of detail (cache_lod.h): far static faces read their open patch's coarse entries.
        // The host chose from the previous frame's pixels, so where this frame's level has no
        // entry yet the other level (if the patch is open) stands in.
        // A near pixel asks whether its patch is open (eight voxel reads) only when its own level
        // has nothing.
        bool lod = set == CACHE_SET_STATIC && gCache.lodDistance > 0.0;
        bool far = uintBitsToFloat(g.data.y) >= gCache.lodDistance;
        uint coarse = 0u;
        ivec3 patchBase;
        if (lod && far) coarse = cacheCoarsePatch(g.voxel.xyz, face, patchBase);
        vec4 r = gatherLevel(g.voxel.xyz, face, set, g.position.xyz, far ? coarse : 0u);
        if (r.w == 0.0 && lod && !far) coarse = cacheCoarsePatch(g.voxel.xyz, face, patchBase);
        if (r.w == 0.0 && coarse != 0u) r = gatherLevel(g.voxel.xyz, face, set, g.position.xyz, far ? 0u : coarse);
        if (kFallback && r.w == 0.0) r = gatherFallback(g.voxel.xyz, face, set, g.position.xyz, g.voxel.xyz, 1, 0u);
        if (kFallback && r.w == 0.0 && coarse != 0u)
            r = gatherFallback(g.voxel.xyz, face, set, g.position.xyz, patchBase, 2, coarse);
        if (r.w > 0.0) indirect = materialAlbedo(g.data.x) / PI * (r.rgb / r.w);
    }
    gIndirect[index] = vec4(indirect, 1.0);
    gRadiance[index] += vec4(indirect, 0.0);
}
