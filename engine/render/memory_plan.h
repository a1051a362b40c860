// MemoryPlan: what showing a built world will hold at its peak — the CPU grid, its GPU mirror,
// the upload staging, the frame's per-pixel buffers and the memory of each technique the frame
// plan (frame_plan.h) runs — worked out before any of the GPU side is allocated, so a world too
// large for the memory budget (core/memory_budget.h) is refused with one line instead of failing
// inside an allocation.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.h"
#include "lighting/lighting_settings.h"
#include "world/scene.h"

namespace engine::render {

struct MemoryPlan {
    glm::uvec2 frameSize{0};
    std::uint64_t world = 0;  // the CPU brick grid and palette
    std::uint64_t gpuWorld =
        0;                     // its mirror: top grid, super grid, brick pages, page table, palette
    std::uint64_t upload = 0;  // staging for one upload chunk
    std::uint64_t frame = 0;   // the frame's own per-pixel buffers at frameSize
    // The running techniques' (TechniquePlan::deviceBytes): the cache's budget, the cones'
    // volumes, ReSTIR's reservoirs, …
    std::vector<std::pair<std::string_view, std::uint64_t>> techniques;
    std::uint64_t techniqueBytes() const;
    std::uint64_t total() const { return world + gpuWorld + upload + frame + techniqueBytes(); }
};

// `displaySize`: the displayed image's when the lighting resolves to it (0: the frame's size).
MemoryPlan planMemory(const world::Scene& scene, glm::uvec2 frameSize,
                      const lighting::LightingSettings& lighting, glm::uvec2 displaySize = {0, 0});

// "peak   N MiB to show at WxH: world …, gpu world …, …; budget B MiB"
std::string formatMemoryPlan(const MemoryPlan& plan, std::uint64_t budgetBytes);

// An error naming `what` when the plan is over the budget.
Status checkMemoryPlan(const MemoryPlan& plan, std::uint64_t budgetBytes, const std::string& what);

}  // namespace engine::render
