#include "render/passes/trace_rays_pass.h"

#include "core/check.h"
#include "shared/trace_rays.h"

namespace engine::render {

TraceRaysPass::TraceRaysPass(gpu::Context& ctx) : mCtx(ctx) {}

void TraceRaysPass::record(gpu::CommandList& cmd, const Io& io, std::uint32_t rayCount,
                           std::uint32_t mode) {
    static constexpr const char* kShaders[] = {"world/trace_rays_hierarchical",
                                               "world/trace_rays_plain", "world/trace_rays_scene"};
    static_assert(shared::TRACE_MODE_HIERARCHICAL == 0 && shared::TRACE_MODE_PLAIN == 1 &&
                  shared::TRACE_MODE_SCENE == 2);
    CHECK(mode < mPasses.size());
    if (!mPasses[mode])
        mPasses[mode] =
            std::make_unique<ComputePass>(mCtx, "trace_rays", kShaders[mode], bindingCount<Io>());
    mPasses[mode]->record(cmd, io.bindings(), {(rayCount + 63) / 64, 1u});
}

}  // namespace engine::render
