#include "render/passes/trace_rays_pass.h"

#include "gpu/command_list.h"

namespace engine::render {

TraceRaysPass::TraceRaysPass(gpu::Context& ctx) : mPipeline(ctx, "world/trace_rays", 7) {}

void TraceRaysPass::record(gpu::CommandList& cmd, const Io& io, std::uint32_t rayCount) {
    cmd.beginPass("trace_rays");
    mPipeline.dispatch(cmd,
                       {&io.world.info(), &io.world.cells(), &io.world.pageTable(), &io.world.palette(), &io.params,
                        &io.rays, &io.hits},
                       (rayCount + 63) / 64);
    cmd.endPass();
    cmd.barrier();
}

}  // namespace engine::render
