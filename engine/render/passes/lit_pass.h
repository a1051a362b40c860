// LitPass: the shape every pass that samples lights shares — a ComputePass that reads the world
// and the emitter list (scene_bindings.h), then its own buffers from LIT_PASS_BINDING_FIRST on
// (shaders/shared/bindings.h). The technique passes (render/restir/, render/baselines/,
// render/reference/, render/irradiance_cache/) name their buffers in an Io struct whose
// bindings() gives each its binding number; the count of own bindings follows from that list.
#pragma once

#include <string>

#include "render/passes/compute_pass.h"
#include "render/passes/scene_bindings.h"

namespace engine::render {

class LitPass {
public:
    LitPass(gpu::Context& ctx, std::string name, const std::string& shader,
            std::uint32_t ownBindings);
    // `own`: the pass's buffers, at LIT_PASS_BINDING_FIRST and after.
    void record(gpu::CommandList& cmd, const SceneBindings& scene, std::span<const PassBinding> own,
                glm::uvec2 groups);
    // Dispatches one after another, `series[i]` dispatch i's own buffers, timed as one pass
    // (ComputePass::recordSeries).
    void recordSeries(gpu::CommandList& cmd, const SceneBindings& scene,
                      std::span<const std::vector<PassBinding>> series, glm::uvec2 groups);
    // Workgroup counts from `args` at `offset` (ComputePass::recordIndirect).
    void recordIndirect(gpu::CommandList& cmd, const SceneBindings& scene,
                        std::span<const PassBinding> own, const gpu::Buffer& args,
                        std::uint64_t offset);

private:
    std::vector<PassBinding> withScene(const SceneBindings& scene,
                                       std::span<const PassBinding> own) const;

    ComputePass mPass;
};

// A LitPass over the image whose own buffers are an Io struct's (see bindingCount): a technique
// pass that shades pixels derives from it and names only its label and shader.
template <class Io>
class ScreenLitPass {
public:
    ScreenLitPass(gpu::Context& ctx, std::string name, const std::string& shader)
        : mPass(ctx, std::move(name), shader, bindingCount<Io>()) {}
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, io.bindings(), screenGroups(size));
    }
    // One dispatch per Io of `series`, timed as one pass (LitPass::recordSeries).
    void recordSeries(gpu::CommandList& cmd, const SceneBindings& scene, std::span<const Io> series,
                      glm::uvec2 size) {
        std::vector<std::vector<PassBinding>> own;
        for (const Io& io : series) {
            const auto b = io.bindings();
            own.emplace_back(b.begin(), b.end());
        }
        mPass.recordSeries(cmd, scene, own, screenGroups(size));
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
