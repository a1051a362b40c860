// Rays against the whole scene: the static world and the dynamic grid, nearer hit wins.
//
// CPU reference of shaders/common/scene_trace.glsl (same operations, same order; the build's
// -ffp-contract=off and the shader's `precise` keep them bit-identical). The two grids have
// different origins, so their traversal distances are not compared directly: each hit is
// measured by faceHitT, the distance to the plane of the face it entered through, computed the
// same way for both. The static world is traced first and bounds the dynamic trace; ties go to
// the static world.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

#include "world/brick_grid.h"
#include "world/dynamic_grid.h"

namespace engine::world {

struct SceneHit {
    bool hit = false;
    glm::ivec3 voxel{0};  // world voxel coordinates
    std::uint32_t face = shared::FACE_NONE;
    float t = 0.0f;  // the traversal's distance (in units of |d|) to the entry face
    std::uint32_t material = 0;
    std::uint32_t steps = 0;  // DDA steps of both traversals
    bool dynamicSet = false;  // the voxel belongs to the dynamic grid
};

// Distance along (o, d) to the plane of `face` of `voxel` (0 for FACE_INSIDE, +inf for
// FACE_NONE). Used to compare hits.
float faceHitT(glm::vec3 o, glm::vec3 d, glm::ivec3 voxel, std::uint32_t face);

// Whether the segment [0, tMax] comes within a voxel of a box of dyn.occupancy (the test the
// shaders make with the same code, shared::segmentNearsBox).
bool nearsOccupancy(const DynamicGrid& dyn, glm::vec3 o, glm::vec3 d, float tMax);

// Dynamic grid only; voxel in world coordinates (grid-local + origin). A miss with no steps when
// the segment nears no occupied box.
SceneHit traceDynamic(const DynamicGrid& dyn, glm::vec3 o, glm::vec3 d, float tMax);

// Static first; ts = faceHitT(static hit) (tMax if none); then dynamic with tMax = ts; the
// dynamic hit wins only if hit && faceHitT(dynamic hit) < ts (strict: static wins ties).
SceneHit traceScene(const BrickGrid& staticGrid, const DynamicGrid* dyn, glm::vec3 o, glm::vec3 d,
                    float tMax);

}  // namespace engine::world
