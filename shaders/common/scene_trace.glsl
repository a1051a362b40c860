// TEMPORARY static-only stand-in for the dynamic-objects branch's scene_trace.glsl (same API).
#ifndef COMMON_SCENE_TRACE_GLSL
#define COMMON_SCENE_TRACE_GLSL

#include "common/brick_traversal.glsl"

struct SceneHit {
    bool hit;
    ivec3 voxel;
    uint face;
    float t;
    uint material;
    uint steps;
    bool dynamicSet;
};

bool dynamicGridPresent() { return false; }

float faceHitT(vec3 o, vec3 d, ivec3 voxel, uint face) {
    if (face >= 6u) return 0.0;
    uint axis = face >> 1u;
    precise float plane = float(voxel[axis]) + ((face & 1u) != 0u ? 1.0 : 0.0);
    precise float t = (plane - o[axis]) / d[axis];
    return t;
}

SceneHit traceDynamic(vec3 o, vec3 d, float tMax) { return SceneHit(false, ivec3(0), FACE_NONE, 0.0, 0u, 0u, true); }

SceneHit traceScene(vec3 o, vec3 d, float tMax) {
    TraceResult r = traceRay(o, d, tMax, true);
    return SceneHit(r.hit, r.voxel, r.face, r.t, r.material, r.steps, false);
}

uint staticVoxelMaterial(ivec3 v) {
    if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, gWorld.sizeInVoxels.xyz))) return 0u;
    uint cell = worldCell(v >> 3);
    if (cell == CELL_EMPTY) return 0u;
    if ((cell & CELL_HOMOGENEOUS) != 0u) return cell & CELL_MATERIAL_MASK;
    ivec3 l = v & 7;
    return brickMaterial(cell - 1u, uint(l.x + 8 * l.y + 64 * l.z));
}

uint dynamicVoxelMaterial(ivec3 v) { return 0u; }

#endif
