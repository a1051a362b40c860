#include "render/passes/lit_pass.h"

#include <vector>

#include "shared/bindings.h"

namespace engine::render {

LitPass::LitPass(gpu::Context& ctx, std::string name, const std::string& shader, std::uint32_t ownBindings)
    : mPass(ctx, std::move(name), shader, shared::LIT_PASS_BINDING_FIRST + ownBindings) {}

void LitPass::record(gpu::CommandList& cmd, const SceneBindings& scene, std::span<const PassBinding> own,
                     glm::uvec2 groups) {
    const auto first = sceneBindings(scene);
    std::vector<PassBinding> bindings(first.begin(), first.end());
    bindings.insert(bindings.end(), own.begin(), own.end());
    mPass.record(cmd, bindings, groups);
}

}  // namespace engine::render
