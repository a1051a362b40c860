#include "render/passes/trace_rays_pass.h"

#include "core/check.h"
#include "gpu/command_list.h"
#include "shared/trace_rays.h"

namespace engine::render {

TraceRaysPass::TraceRaysPass(gpu::Context& ctx) : mCtx(ctx) {}

void TraceRaysPass::record(gpu::CommandList& cmd, const Io& io, std::uint32_t rayCount, std::uint32_t mode) {
    static constexpr const char* kShaders[] = {"world/trace_rays_hierarchical", "world/trace_rays_plain",
                                               "world/trace_rays_scene"};
    static_assert(shared::TRACE_MODE_HIERARCHICAL == 0 && shared::TRACE_MODE_PLAIN == 1 &&
                  shared::TRACE_MODE_SCENE == 2);
    CHECK(mode < mPipelines.size());
    if (!mPipelines[mode]) mPipelines[mode] = std::make_unique<gpu::ComputePipeline>(mCtx, kShaders[mode], 7);
    cmd.beginPass("trace_rays");
    mPipelines[mode]->dispatch(cmd,
                               {&io.world.info(), &io.world.cells(), &io.world.pageTable(), &io.world.palette(),
                                &io.params, &io.rays, &io.hits},
                               (rayCount + 63) / 64);
    cmd.endPass();
    cmd.barrier();
}

}  // namespace engine::render
