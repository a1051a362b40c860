#include "render/loop_budget.h"

#include <algorithm>

#include "shared/brick_grid.h"
#include "shared/dynamic_grid.h"
#include "world/scene.h"

namespace engine::render {

namespace {

// The fixed-count loops around one ray: fewer than 64 passes even if the compiler unrolls none
// (emitters.glsl's face loops 3 + 6 + 6 + 6, two entry tests of 3 axes, the 4 × 4 matrix, the
// caller's loop's own pass).
constexpr std::uint32_t kFixedPassesPerRay = 64;

// emitter_lookup.glsl: a voxel's six neighbours, or a cell's six sides of 8 × 8 voxels with
// their row and side loops (6 + 6 × (1 + 8 + 64)).
constexpr std::uint32_t kEmitterLookupPasses = 6 + 6 * (1 + 8 + 64);

std::uint32_t traversalSteps(glm::ivec3 size) {
    const auto planes = std::uint64_t(size.x) + std::uint64_t(size.y) + std::uint64_t(size.z);
    return static_cast<std::uint32_t>(
        std::min<std::uint64_t>(planes + 1, shared::TRAVERSAL_MAX_STEPS));
}

}  // namespace

std::uint32_t rayLoopPasses(const world::Scene& scene) {
    std::uint32_t passes = kFixedPassesPerRay + traversalSteps(scene.grid.sizeInVoxels());
    if (scene.dynamic.present())
        passes +=
            shared::DYNAMIC_OCCUPANCY_BOXES + traversalSteps(scene.dynamic.grid.sizeInVoxels());
    return passes;
}

std::uint32_t shadowRaysPerDispatch(const world::Scene& scene) {
    const std::uint32_t perRay = rayLoopPasses(scene);
    const std::uint32_t rays = kLoopPlan / perRay;  // the sun's shadow ray is one of them
    return std::max(rays, 2u) - 1u;
}

std::uint32_t pathSampleLoopPasses(const world::Scene& scene, std::uint32_t bounces) {
    const std::uint64_t ray = rayLoopPasses(scene);
    const std::uint64_t vertex = 1 + 3 * ray + kEmitterLookupPasses;
    const std::uint64_t passes = 1 + ray + (std::uint64_t(bounces) + 1) * vertex;
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(passes, kLoopBudget));
}

std::uint32_t referenceSamplesPerDispatch(const world::Scene& scene, std::uint32_t bounces) {
    return std::max(kLoopPlan / pathSampleLoopPasses(scene, bounces), 1u);
}

}  // namespace engine::render
