// Rays against the whole scene: the static world and the dynamic grid, nearer hit wins.
// Mirrors engine/world/scene_trace.cpp operation for operation (`precise` here,
// -ffp-contract=off there); read that header for the rules. Every shader that traces rays for
// shading uses traceScene, so objects are seen and cast shadows everywhere.
#ifndef COMMON_SCENE_TRACE_GLSL
#define COMMON_SCENE_TRACE_GLSL

#include "common/brick_traversal.glsl"

struct SceneHit {
    bool hit;
    ivec3 voxel;  // world voxel coordinates
    uint face;
    float t;
    uint material;
    uint steps;
    bool dynamicSet;
};

SceneHit sceneHitFrom(TraceResult r, ivec3 origin, bool dynamicSet) {
    return SceneHit(r.hit, r.voxel + origin, r.hit ? r.face : FACE_NONE, r.t, r.material, r.steps, r.hit && dynamicSet);
}

// Distance along (o, d) to the plane of `face` of `voxel` (0 for FACE_INSIDE, +inf for FACE_NONE).
float faceHitT(vec3 o, vec3 d, ivec3 voxel, uint face) {
    if (face == FACE_INSIDE) return 0.0;
    if (face >= 6u) return uintBitsToFloat(0x7f800000u);
    int axis = int(face >> 1u);
    precise float plane = float(voxel[axis] + int(face & 1u));
    precise float inv = 1.0 / d[axis];
    precise float t = (plane - o[axis]) * inv;
    return t;
}

// The coarse occupancy (shared/dynamic_grid.h): whether the segment comes near a box of cells
// that hold an object this frame. One test per box, read from the header's texels.
bool dynamicOccupancyNear(vec3 o, vec3 d, float tMax) {
    uint boxes = dynamicTexel(21u);  // header.objects.y
    bool near = false;
    for (uint i = 0u; i < boxes; ++i) {
        ivec3 lo = dynamicTexels3(DYNAMIC_HEADER_OCCUPIED_MIN + 4u * i);
        ivec3 hi = dynamicTexels3(DYNAMIC_HEADER_OCCUPIED_MAX + 4u * i);
        near = near || segmentNearsBox(o, d, tMax, lo, hi);
    }
    return near;
}

// Dynamic grid only; voxel in world coordinates (grid-local + origin). A ray that nears no
// occupied box misses without a traversal (world/scene_trace.cpp does the same). Where a SIMD
// batch or warp skips a branch none of its lanes take (GPUs; later lavapipes, whose gallivm skips
// such branches: lp_build_skip_branch), a batch of rays far from every object skips the
// traversal's code. The lavapipe of docs/PERFORMANCE.md (Mesa 22.3) runs every branch and one
// pass of every loop under an empty mask, so there the test saves nothing (docs/PERFORMANCE.md, "A small object far from
// the camera").
SceneHit traceDynamic(vec3 o, vec3 d, float tMax) {
    SceneHit h = sceneHitFrom(traceMiss(0u), ivec3(0), false);
    if (!dynamicGridPresent()) return h;
    if (dynamicOccupancyNear(o, d, tMax)) {
        loadDynamicGrid();
        ivec3 origin = gDynHeader.origin.xyz;
        precise vec3 local = o - vec3(origin);
        h = sceneHitFrom(traceGrid(local, d, tMax, true, true), origin, true);
    }
    return h;
}

// Static first; ts = faceHitT(static hit) (tMax if none); then dynamic with tMax = ts; the
// dynamic hit wins only if hit && faceHitT(dynamic hit) < ts (strict: static wins ties).
SceneHit traceScene(vec3 o, vec3 d, float tMax) {
    SceneHit s = sceneHitFrom(traceGrid(o, d, tMax, true, false), ivec3(0), false);
    if (!dynamicGridPresent()) return s;
    float ts = s.hit ? faceHitT(o, d, s.voxel, s.face) : tMax;
    SceneHit h = traceDynamic(o, d, ts);
    h.steps += s.steps;
    if (h.hit && faceHitT(o, d, h.voxel, h.face) < ts) return h;
    s.steps = h.steps;
    return s;
}

uint staticVoxelMaterial(ivec3 v) { return gridVoxelMaterial(false, v); }
bool staticVoxelSolid(ivec3 v) { return gridVoxelSolid(false, v); }

// World coordinates; false outside or with no dynamic grid.
bool dynamicVoxelSolid(ivec3 v) {
    if (!dynamicGridPresent()) return false;
    loadDynamicGrid();
    return gridVoxelSolid(true, v - gDynHeader.origin.xyz);
}

// World coordinates; 0 = empty, outside or no dynamic grid.
uint dynamicVoxelMaterial(ivec3 v) {
    if (!dynamicGridPresent()) return 0u;
    loadDynamicGrid();
    return gridVoxelMaterial(true, v - gDynHeader.origin.xyz);
}

// The object whose bounds hold world voxel v (the first, where bounds overlap); -1 if none.
int dynamicObjectAt(ivec3 v) {
    if (!dynamicGridPresent()) return -1;
    uint count = dynamicObjectCount();
    for (uint i = 0u; i < count; ++i) {
        if (all(greaterThanEqual(v, dynamicObjectBoundsMin(i))) && all(lessThan(v, dynamicObjectBoundsMax(i)))) return int(i);
    }
    return -1;
}

#endif
