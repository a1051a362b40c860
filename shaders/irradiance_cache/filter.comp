#version 460
// Irradiance cache, smoothing (§4.7): a 3^3 binomial (Gaussian-like) filter over the same face of
// the neighbouring entries of the same set. Empty neighbours and unexposed faces take no part, so
// values never cross a one-voxel wall (its two sides are different faces). A coarse entry (one
// face of an open 2x2 patch) filters over the neighbouring patches of its plane.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = CACHE_GROUP_SIZE) in;

void main() {
    // One invocation per listed (exposed) face, as the bounce; closed faces got 0 in cache.faces.
    uint item, face;
    if (!cacheUpdateListedFace(cacheThread(), item, face)) return;
    uint slot = gLists[item];
    CacheEntry entry = gEntries[slot];
    uint index = slot * CACHE_FACES + face;
    vec4 own = gIrradiance[index];
    if ((gCache.flags & CACHE_FLAG_NO_FILTER) != 0u || own.w == 0.0) {
        gFiltered[index] = vec4(own.rgb, own.w > 0.0 ? 1.0 : 0.0);
        return;
    }
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    if (entry.coarse != 0u) {
        // A coarse entry: 3x3 over the neighbouring patches of its plane and face. Two open patches
        // side by side share an open front, so no one-voxel wall stands between them.
        uint axis = face >> 1u, ua = (axis + 1u) % 3u, va = (axis + 2u) % 3u;
        for (int y = -1; y <= 1; ++y) {
            for (int x = -1; x <= 1; ++x) {
                ivec3 v = entry.voxel.xyz;
                v[ua] += 2 * x;
                v[va] += 2 * y;
                uint n = x == 0 && y == 0 ? slot : cacheLookupKey(v, CACHE_SET_STATIC, entry.coarse);
                if (n == ~0u) continue;
                vec4 c = gIrradiance[n * CACHE_FACES + face];
                if (c.w == 0.0) continue;
                float w = float((2 - abs(x)) * (2 - abs(y)));
                sum += w * c.rgb;
                weights += w;
            }
        }
        gFiltered[index] = vec4(sum / weights, 1.0);
        return;
    }
    for (int z = -1; z <= 1; ++z) {
        for (int y = -1; y <= 1; ++y) {
            for (int x = -1; x <= 1; ++x) {
                ivec3 o = ivec3(x, y, z);
                uint n = o == ivec3(0) ? slot : cacheLookup(entry.voxel.xyz + o, uint(entry.voxel.w));
                if (n == ~0u) continue;
                vec4 v = gIrradiance[n * CACHE_FACES + face];
                if (v.w == 0.0) continue;
                float w = float((2 - abs(x)) * (2 - abs(y)) * (2 - abs(z)));
                sum += w * v.rgb;
                weights += w;
            }
        }
    }
    gFiltered[index] = vec4(sum / weights, 1.0);
}
