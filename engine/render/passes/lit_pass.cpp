#include "render/passes/lit_pass.h"

#include <vector>

#include "shared/bindings.h"

namespace engine::render {

LitPass::LitPass(gpu::Context& ctx, std::string name, const std::string& shader,
                 std::uint32_t ownBindings)
    : mPass(ctx, std::move(name), shader, shared::LIT_PASS_BINDING_FIRST + ownBindings) {}

std::vector<PassBinding> LitPass::withScene(const SceneBindings& scene,
                                            std::span<const PassBinding> own) const {
    const auto first = sceneBindings(scene);
    std::vector<PassBinding> bindings(first.begin(), first.end());
    bindings.insert(bindings.end(), own.begin(), own.end());
    return bindings;
}

void LitPass::record(gpu::CommandList& cmd, const SceneBindings& scene,
                     std::span<const PassBinding> own, glm::uvec2 groups) {
    mPass.record(cmd, withScene(scene, own), groups);
}

void LitPass::recordSeries(gpu::CommandList& cmd, const SceneBindings& scene,
                           std::span<const std::vector<PassBinding>> series, glm::uvec2 groups) {
    std::vector<std::vector<PassBinding>> all;
    for (const std::vector<PassBinding>& own : series) all.push_back(withScene(scene, own));
    mPass.recordSeries(cmd, all, groups);
}

void LitPass::recordIndirect(gpu::CommandList& cmd, const SceneBindings& scene,
                             std::span<const PassBinding> own, const gpu::Buffer& args,
                             std::uint64_t offset) {
    mPass.recordIndirect(cmd, withScene(scene, own), args, offset);
}

}  // namespace engine::render
