#include "render/passes/primary_ray_pass.h"

#include "gpu/command_list.h"

namespace engine::render {

PrimaryRayPass::PrimaryRayPass(gpu::Context& ctx) : mPipeline(ctx, "world/primary_rays", 6) {}

void PrimaryRayPass::record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size) {
    cmd.beginPass("primary_rays");
    mPipeline.dispatch(cmd,
                       {&io.world.info(), &io.world.cells(), &io.world.pageTable(), &io.world.palette(),
                        &io.frameParams, &io.gbuffer},
                       (size.x + 7) / 8, (size.y + 7) / 8);
    cmd.endPass();
    cmd.barrier();
}

}  // namespace engine::render
