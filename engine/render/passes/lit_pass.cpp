#include "render/passes/lit_pass.h"

#include "core/check.h"
#include "gpu/command_list.h"

namespace engine::render {

LitPass::LitPass(gpu::Context& ctx, std::string name, const std::string& shader, std::uint32_t ownBindings)
    : mName(std::move(name)), mOwnBindings(ownBindings), mPipeline(ctx, shader, 8 + ownBindings) {}

void LitPass::record(gpu::CommandList& cmd, const SceneBindings& scene, std::initializer_list<const gpu::Buffer*> own,
                     glm::uvec2 size) {
    CHECK(own.size() == mOwnBindings);
    std::vector<const gpu::Buffer*> buffers{&scene.world.info(),   &scene.world.cells(),     &scene.world.pageTable(),
                                            &scene.world.palette(), &scene.lights.info(),    &scene.lights.emitters(),
                                            &scene.lights.alive(),  &scene.lights.alias()};
    buffers.insert(buffers.end(), own.begin(), own.end());
    cmd.beginPass(mName);
    mPipeline.dispatch(cmd, buffers, (size.x + 7) / 8, (size.y + 7) / 8);
    cmd.endPass();
    cmd.barrier();
}

}  // namespace engine::render
