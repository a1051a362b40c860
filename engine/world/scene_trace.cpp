#include "world/scene_trace.h"

#include <limits>

#include "shared/dynamic_grid.h"
#include "world/ray_traversal.h"

namespace engine::world {

namespace {
SceneHit fromRayHit(const RayHit& h, glm::ivec3 origin, bool dynamicSet) {
    return SceneHit{
        h.hit,   h.voxel + origin,   h.hit ? h.face : shared::FACE_NONE, h.t, h.material,
        h.steps, h.hit && dynamicSet};
}
}  // namespace

float faceHitT(glm::vec3 o, glm::vec3 d, glm::ivec3 voxel, std::uint32_t face) {
    if (face == shared::FACE_INSIDE) return 0.0f;
    if (face >= 6u) return std::numeric_limits<float>::infinity();
    const int axis = int(face >> 1u);
    // Face 2a is the voxel's low side on axis a, face 2a+1 its high side.
    // Multiply by the reciprocal as the traversal does: 1/x is exact on the GPU, x/y need not be.
    const float plane = float(voxel[axis] + int(face & 1u));
    const float inv = 1.0f / d[axis];
    return (plane - o[axis]) * inv;
}

bool nearsOccupancy(const DynamicGrid& dyn, glm::vec3 o, glm::vec3 d, float tMax) {
    for (const Box& b : dyn.occupancy)
        if (shared::segmentNearsBox(o, d, tMax, b.min, b.max)) return true;
    return false;
}

SceneHit traceDynamic(const DynamicGrid& dyn, glm::vec3 o, glm::vec3 d, float tMax) {
    if (!dyn.present() || !nearsOccupancy(dyn, o, d, tMax)) return SceneHit{};
    const glm::vec3 local = o - glm::vec3(dyn.origin);
    return fromRayHit(traceRay(dyn.grid, Ray{local, d, tMax}), dyn.origin, true);
}

SceneHit traceScene(const BrickGrid& staticGrid, const DynamicGrid* dyn, glm::vec3 o, glm::vec3 d,
                    float tMax) {
    SceneHit s = fromRayHit(traceRay(staticGrid, Ray{o, d, tMax}), glm::ivec3(0), false);
    if (!dyn || !dyn->present()) return s;
    const float ts = s.hit ? faceHitT(o, d, s.voxel, s.face) : tMax;
    SceneHit h = traceDynamic(*dyn, o, d, ts);
    h.steps += s.steps;
    if (h.hit && faceHitT(o, d, h.voxel, h.face) < ts) return h;
    s.steps = h.steps;
    return s;
}

}  // namespace engine::world
