// Light-sampling baselines: N light samples with N shadow rays per pixel, or every light once.
// Shader: shaders/lighting/light_sampling.comp
#pragma once

#include "render/passes/lit_pass.h"

namespace engine::render {

class LightSamplingPass {
public:
    explicit LightSamplingPass(gpu::Context& ctx) : mPass(ctx, "light_sampling", "lighting/light_sampling", 4) {}
    struct Io {
        const gpu::Buffer& frameParams;   // read
        const gpu::Buffer& restirParams;  // read
        const gpu::Buffer& gbuffer;       // read
        gpu::Buffer& radiance;            // write
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, {&io.frameParams, &io.restirParams, &io.gbuffer, &io.radiance}, size);
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
