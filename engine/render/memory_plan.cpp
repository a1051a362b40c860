#include "render/memory_plan.h"

#include <algorithm>
#include <bit>
#include <fmt/format.h>

#include "core/memory_budget.h"
#include "gpu/uploader.h"
#include "render/frame_plan.h"
#include "render/renderer.h"
#include "shared/brick_grid.h"
#include "shared/material.h"

namespace engine::render {

namespace {
double mib(std::uint64_t bytes) { return double(bytes) / double(1 << 20); }
}  // namespace

MemoryPlan planMemory(const world::Scene& scene, glm::uvec2 frameSize,
                      const lighting::LightingSettings& lighting, glm::uvec2 displaySize) {
    // From the grid's own counts: cheap enough for every new world the renderer meets.
    const world::GridMemory grid = scene.grid.memory();
    const std::uint64_t palette = scene.palette.size() * sizeof(shared::GpuMaterial);
    MemoryPlan plan;
    plan.frameSize = frameSize;
    plan.world = grid.topGridBytes + grid.superGridBytes + grid.brickPoolBytes +
                 grid.bookkeepingBytes + palette;
    const std::uint64_t bricks = scene.grid.brickCapacity();
    const std::uint64_t pages = std::max<std::uint64_t>(
        1, (bricks + shared::BRICK_PAGE_BRICKS - 1) / shared::BRICK_PAGE_BRICKS);
    // The pages, the page table, and the copy of every brick slot's masks beside the top grid.
    plan.gpuWorld =
        grid.topGridBytes + grid.superGridBytes + palette +
        pages * std::uint64_t(shared::BRICK_PAGE_WORDS) * 4u +
        std::max<std::uint64_t>(64, std::bit_ceil(pages)) * sizeof(std::uint64_t) +
        pages * shared::BRICK_PAGE_BRICKS * std::uint64_t(shared::BRICK_MASK_WORDS) * 4u;
    plan.upload = std::min<std::uint64_t>(gpu::Uploader::kChunkBytes,
                                          std::bit_ceil(plan.gpuWorld));  // one chunk at most
    plan.frame = std::uint64_t(frameSize.x) * frameSize.y * Renderer::frameBytesPerPixel();
    const FramePlan frame = planFrame(lighting, sceneShape(scene), frameSize);
    if (frame.writesDisplay) {
        const glm::uvec2 display = displaySize.x != 0 ? displaySize : frameSize;
        plan.frame += std::uint64_t(display.x) * display.y * Renderer::displayBytesPerPixel();
    }
    for (const FramePlan::Step& step : frame.steps) {
        if (step.plan.runs && step.plan.deviceBytes)
            plan.techniques.emplace_back(step.technique->name, step.plan.deviceBytes);
    }
    return plan;
}

std::uint64_t MemoryPlan::techniqueBytes() const {
    std::uint64_t bytes = 0;
    for (const auto& [name, b] : techniques) bytes += b;
    return bytes;
}

std::string formatMemoryPlan(const MemoryPlan& plan, std::uint64_t budgetBytes) {
    return fmt::format(
        "{:.0f} MiB to show at {}x{}: world {:.0f}, gpu world {:.0f}, upload staging {:.0f}, frame "
        "buffers {:.0f}, techniques {:.0f}; budget {:.0f} MiB ({})",
        mib(plan.total()), plan.frameSize.x, plan.frameSize.y, mib(plan.world), mib(plan.gpuWorld),
        mib(plan.upload), mib(plan.frame), mib(plan.techniqueBytes()), mib(budgetBytes),
        addressSpaceLimits(budgetBytes) ? "3/4 of ulimit -v" : "--memory-budget");
}

Status checkMemoryPlan(const MemoryPlan& plan, std::uint64_t budgetBytes, const std::string& what) {
    if (plan.total() <= budgetBytes) return {};
    return makeError(
        "{} needs {:.0f} MiB to show ({:.0f} the world, {:.0f} its GPU copy, {:.0f} the rest), "
        "over the memory budget of {:.0f} MiB: make the world smaller, or {}",
        what, mib(plan.total()), mib(plan.world), mib(plan.gpuWorld),
        mib(plan.upload + plan.frame + plan.techniqueBytes()), mib(budgetBytes),
        memoryBudgetAdvice(budgetBytes));
}

}  // namespace engine::render
