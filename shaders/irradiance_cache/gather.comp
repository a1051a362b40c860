#version 460
// Irradiance cache, final gather (§4.8): a pixel reads the face its normal points along from its
// set's entries (static pixels the static set only: dynamic objects never leak into static
// surfaces), bilinearly across the neighbouring voxels in the face's plane. Neighbours without a
// value drop out and the weights renormalise: the padding of §4.7 without storing padded voxels.
// Adds albedo/pi * E to the frame's radiance.
#extension GL_GOOGLE_include_directive : require

#include "irradiance_cache/irradiance_cache.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, uvec2(gCache.width, gCache.height)))) return;
    uint index = pixel.x + pixel.y * gCache.width;
    GBufferTexel g = gGBuffer[index];
    uint face = uint(g.voxel.w);
    vec3 indirect = vec3(0.0);
    if (face < 6u) {
        uint set = (g.data.w & GBUFFER_FLAG_DYNAMIC) != 0u ? CACHE_SET_DYNAMIC : CACHE_SET_STATIC;
        uint axis = face >> 1u, ua = (axis + 1u) % 3u, va = (axis + 2u) % 3u;
        vec3 p = g.position.xyz;
        vec2 uv = vec2(p[ua], p[va]) - 0.5;
        ivec2 base = ivec2(floor(uv));
        vec2 f = uv - vec2(base);
        vec3 sum = vec3(0.0);
        float weights = 0.0;
        for (int j = 0; j <= 1; ++j) {
            for (int i = 0; i <= 1; ++i) {
                ivec3 v = g.voxel.xyz;
                v[ua] = base.x + i;
                v[va] = base.y + j;
                uint slot = cacheLookup(v, set);
                if (slot == ~0u) continue;
                vec4 e = gFiltered[slot * CACHE_FACES + face];
                if (e.w == 0.0) continue;
                float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) + 1e-6;
                sum += w * e.rgb * cacheFade(slot);
                weights += w;
            }
        }
        if (weights > 0.0) indirect = gMaterials[g.data.x].albedo.rgb / PI * (sum / weights);
    }
    gIndirect[index] = vec4(indirect, 1.0);
    gRadiance[index] += vec4(indirect, 0.0);
}
