#include "render/passes/sun_shade_pass.h"

#include "gpu/command_list.h"

namespace engine::render {

SunShadePass::SunShadePass(gpu::Context& ctx) : mPipeline(ctx, "world/shade_sun", 8) {}

void SunShadePass::record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size) {
    cmd.beginPass("shade_sun");
    mPipeline.dispatch(cmd,
                       {&io.world.info(), &io.world.cells(), &io.world.pageTable(), &io.world.palette(),
                        &io.frameParams, &io.gbuffer, &io.radiance, &io.rayStats},
                       (size.x + 7) / 8, (size.y + 7) / 8);
    cmd.endPass();
    cmd.barrier();
}

}  // namespace engine::render
