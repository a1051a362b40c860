// MemoryPlan: what showing a built world will hold at its peak — the CPU grid, its GPU mirror,
// the upload staging, the frame's per-pixel buffers and the irradiance cache's budget — worked
// out before any of the GPU side is allocated, so a world too large for the memory budget
// (core/memory_budget.h) is refused with one line instead of failing inside an allocation.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "core/error.h"
#include "lighting/lighting_settings.h"
#include "world/scene.h"

namespace engine::render {

struct MemoryPlan {
    glm::uvec2 frameSize{0};
    std::uint64_t world = 0;     // the CPU brick grid and palette
    std::uint64_t gpuWorld = 0;  // its mirror: top grid, super grid, brick pages, page table, palette
    std::uint64_t upload = 0;    // staging for one upload chunk
    std::uint64_t frame = 0;     // per-pixel buffers at frameSize
    std::uint64_t cache = 0;     // the irradiance cache's budget, or the cones' volumes, when on
    std::uint64_t total() const { return world + gpuWorld + upload + frame + cache; }
};

MemoryPlan planMemory(const world::Scene& scene, glm::uvec2 frameSize, const lighting::LightingSettings& lighting);

// "peak   N MiB to show at WxH: world …, gpu world …, …; budget B MiB"
std::string formatMemoryPlan(const MemoryPlan& plan, std::uint64_t budgetBytes);

// An error naming `what` when the plan is over the budget.
Status checkMemoryPlan(const MemoryPlan& plan, std::uint64_t budgetBytes, const std::string& what);

}  // namespace engine::render
