// One Vulkan context per GPU test binary, with validation layers required; GpuTest fails any test
// during which the layers reported an error.
#pragma once

#include <gtest/gtest.h>
#include <vector>

#include "gpu/context.h"
#include "shared/trace_rays.h"
#include "world/ray_traversal.h"
#include "world/scene.h"

namespace engine::render {
class GpuWorld;
}

namespace gpu_testing {

engine::gpu::Context& context();

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override { mErrorsBefore = context().validationErrors(); }
    void TearDown() override {
        EXPECT_EQ(context().validationErrors(), mErrorsBefore)
            << "Vulkan validation reported errors (see stderr)";
    }

private:
    std::uint32_t mErrorsBefore = 0;
};

// A scene around `grid` with a palette of `materials` plain materials (ids 1..materials).
engine::world::Scene sceneWith(engine::world::BrickGrid grid, int materials = 8);

// Traces `rays` on the GPU through `scene` (uploaded fresh) and returns the raw outputs.
std::vector<shared::TraceRayOutput> traceOnGpu(
    engine::world::Scene& scene, const std::vector<engine::world::Ray>& rays,
    std::uint32_t mode = shared::TRACE_MODE_HIERARCHICAL);
// The same through a GPU world that lives on between calls: after the first call only what the
// scene's edits dirtied is uploaded (the grid's dirty lists are cleared, as the renderer does).
std::vector<shared::TraceRayOutput> traceOnGpu(
    engine::render::GpuWorld& world, engine::world::Scene& scene,
    const std::vector<engine::world::Ray>& rays,
    std::uint32_t mode = shared::TRACE_MODE_HIERARCHICAL);

}  // namespace gpu_testing
