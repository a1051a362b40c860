// Scene rays traced in order of cost within an 8x8 workgroup. llvmpipe runs a workgroup as SIMD
// batches of 8 lanes (one row of 8 pixels) and each batch walks its traversal loop until its
// longest ray is done, so a short ray beside a long one idles. Here every invocation posts its ray
// to shared memory, ranks it by a cost key among the 64 (a count, no sort loop), traces the ray of
// its own rank and posts the answer back: a batch then holds rays of similar cost. The same rays
// are traced with the same arithmetic, so every pixel gets the bit-identical hit.
// Call traceSceneSorted from every invocation of the workgroup in uniform control flow (it holds
// barriers): a pixel outside the image or without a ray passes hasRay = false.
#ifndef COMMON_RAY_SORT_GLSL
#define COMMON_RAY_SORT_GLSL

#include "common/scene_trace.glsl"

#define RAY_SORT_GROUP 64u  // local_size_x * local_size_y of every shader that includes this

shared vec4 sSortOrigin[RAY_SORT_GROUP];     // by invocation: origin, tMax
shared vec4 sSortDirection[RAY_SORT_GROUP];  // by invocation: direction, cost key (< 0: no ray)
shared uint sSortRay[RAY_SORT_GROUP];        // by rank: the invocation whose ray it is
shared uvec4 sSortHit[RAY_SORT_GROUP];       // by invocation: voxel, face | hit << 8 | dynamic << 9
shared uvec4 sSortHitMore[RAY_SORT_GROUP];   // by invocation: t bits, material, steps

#ifndef RAY_SORT_KEY
#define RAY_SORT_KEY 1
#endif

// Cost key of a ray: its length inside the static world's box (a ray to the sun has tMax 1e30 but
// stops at the world's edge), optionally grouped by direction octant first.
float raySortKey(vec3 o, vec3 d, float tMax) {
    vec3 size = vec3(gridSizeInVoxels(false));
    vec3 inv = 1.0 / d;  // +-inf on an axis the ray does not move along: that slab never ends it
    vec3 tFar = max((vec3(0.0) - o) * inv, (size - o) * inv);
    float span = clamp(min(tMax, min(tFar.x, min(tFar.y, tFar.z))), 0.0, 1.0e6);
#if RAY_SORT_KEY == 2
    uint octant = (d.x < 0.0 ? 1u : 0u) + (d.y < 0.0 ? 2u : 0u) + (d.z < 0.0 ? 4u : 0u);
    return float(octant) * 2.0e6 + span;
#else
    return span;
#endif
}

SceneHit traceSceneSorted(bool hasRay, vec3 o, vec3 d, float tMax) {
    uint me = gl_LocalInvocationIndex;
    float key = hasRay ? raySortKey(o, d, tMax) : -1.0;
    sSortOrigin[me] = vec4(o, tMax);
    sSortDirection[me] = vec4(d, key);
    memoryBarrierShared();
    barrier();
#if RAY_SORT_KEY == 0
    uint rank = me;  // unsorted: measures what the barriers and shared memory cost alone
#else
    uint rank = 0u;
    for (uint j = 0u; j < RAY_SORT_GROUP; ++j) {
        float other = sSortDirection[j].w;
        if (other < key || (other == key && j < me)) ++rank;
    }
#endif
    sSortRay[rank] = me;
    memoryBarrierShared();
    barrier();
    uint ray = sSortRay[me];
    vec4 ro = sSortOrigin[ray];
    vec4 rd = sSortDirection[ray];
    SceneHit h = SceneHit(false, ivec3(0), FACE_NONE, 0.0, 0u, 0u, false);
    if (rd.w >= 0.0) h = traceScene(ro.xyz, rd.xyz, ro.w);
    sSortHit[ray] = uvec4(uvec3(h.voxel), h.face | (h.hit ? 1u << 8 : 0u) | (h.dynamicSet ? 1u << 9 : 0u));
    sSortHitMore[ray] = uvec4(floatBitsToUint(h.t), h.material, h.steps, 0u);
    memoryBarrierShared();
    barrier();
    uvec4 a = sSortHit[me];
    uvec4 b = sSortHitMore[me];
    return SceneHit((a.w & (1u << 8)) != 0u, ivec3(a.xyz), a.w & 0xffu, uintBitsToFloat(b.x), b.y, b.z,
                    (a.w & (1u << 9)) != 0u);
}

// lightVisible (common/emitters.glsl) with its shadow ray traced sorted: the same ray, the same
// test of what it hits.
bool lightVisibleSorted(bool hasRay, Surface s, GpuEmitter e, vec3 shadowDir, float shadowDist) {
    SceneHit hit = traceSceneSorted(hasRay, s.position + s.normal * kRayOffset, shadowDir, shadowDist + kRayOffset);
    if (!hit.hit) return true;
    if (hit.dynamicSet) return false;
    ivec3 lo = e.minCorner.xyz;
    return all(greaterThanEqual(hit.voxel, lo)) && all(lessThan(hit.voxel, lo + e.minCorner.w));
}

#endif
