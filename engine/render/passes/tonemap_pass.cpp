#include "render/passes/tonemap_pass.h"

#include "gpu/command_list.h"

namespace engine::render {

TonemapPass::TonemapPass(gpu::Context& ctx) : mPipeline(ctx, "post/tonemap", 3) {}

void TonemapPass::record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size) {
    cmd.beginPass("tonemap");
    mPipeline.dispatch(cmd, {&io.frameParams, &io.radiance, &io.ldr}, (size.x + 7) / 8, (size.y + 7) / 8);
    cmd.endPass();
    cmd.barrier();
}

}  // namespace engine::render
