// Light-sampling baselines: N light samples with N shadow rays per pixel, or every light once.
// Shader: shaders/baselines/light_sampling.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/light_sampling.h"

namespace engine::render {

class LightSamplingPass {
public:
    struct Io {
        const gpu::Buffer& frameParams;  // read
        const gpu::Buffer& params;       // read: LightSamplingParams
        const gpu::Buffer& gbuffer;      // read
        gpu::Buffer& radiance;           // write
        auto bindings() const {
            return std::to_array<PassBinding>({{shared::LIGHT_SAMPLING_BINDING_FRAME, &frameParams},
                                               {shared::LIGHT_SAMPLING_BINDING_PARAMS, &params},
                                               {shared::LIGHT_SAMPLING_BINDING_GBUFFER, &gbuffer},
                                               {shared::LIGHT_SAMPLING_BINDING_RADIANCE, &radiance}});
        }
    };
    explicit LightSamplingPass(gpu::Context& ctx)
        : mPass(ctx, "light_sampling", "baselines/light_sampling", bindingCount<Io>()) {}
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, io.bindings(), screenGroups(size));
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
