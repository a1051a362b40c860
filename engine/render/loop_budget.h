// Lavapipe's loop budget: Mesa 22.3's gallivm lets each SIMD batch of a shader make at most
// LP_MAX_TGSI_LOOP_ITERATIONS = 65 535 loop passes, counted over every loop of the shader
// together; once a batch has spent them, every loop makes one pass at most, so a ray traversal
// stops after one step and reports a miss (docs/PERFORMANCE.md, "Lavapipe's loop budget"). Each
// dispatch starts every batch with the whole budget, so a shader whose loops can spend more
// splits its work across dispatches. These are the bounds the host sizes those dispatches by:
// upper bounds on the passes, from the world's size, never measured counts.
#pragma once

#include <cstdint>

namespace engine::world {
struct Scene;
}

namespace engine::render {

inline constexpr std::uint32_t kLoopBudget = 65535;
// What a dispatch plans to spend at most: half the budget, so the passes the bounds below leave
// out (a loop the shader gains later, a driver that counts differently) still fit.
inline constexpr std::uint32_t kLoopPlan = kLoopBudget / 2;

// Loop passes one ray through the scene (traceScene, shaders/common/scene_trace.glsl) can take,
// with the fixed-count loops around it (sampling one emitter's faces, the entry tests' three
// axes, reading the dynamic grid's matrix). A traversal step leaves a block through a voxel
// plane the ray has not crossed yet, and a ray crosses at most X + Y + Z such planes of a grid
// X × Y × Z voxels, so a traversal takes at most X + Y + Z + 1 steps (and never more than
// TRAVERSAL_MAX_STEPS); the dynamic grid adds its own such bound and one pass per occupancy box.
std::uint32_t rayLoopPasses(const world::Scene& scene);

// Shadow rays per pixel the light-sampling baselines (shaders/baselines/light_sampling.comp:
// brute force's one per emitter, uniform's samples) trace per dispatch, with the sun's shadow
// ray once, within kLoopPlan. At least 1.
std::uint32_t shadowRaysPerDispatch(const world::Scene& scene);

// Loop passes one path sample of the reference path tracer (shaders/reference/path_trace.comp)
// can take with `bounces`: its camera ray, then at each of bounces + 1 vertices the sun's and an
// emitter's shadow rays, the continuation ray and the lookup of the emitter that ray hits
// (emitter_lookup.glsl scans a brick light's six sides, 8 × 8 voxels each).
std::uint32_t pathSampleLoopPasses(const world::Scene& scene, std::uint32_t bounces);

// Samples per pixel the reference path tracer adds per dispatch within kLoopPlan. At least 1.
std::uint32_t referenceSamplesPerDispatch(const world::Scene& scene, std::uint32_t bounces);

}  // namespace engine::render
