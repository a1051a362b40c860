// ReSTIR initial candidates (thesis §4.4-4.5): M light samples per pixel resampled into one
// reservoir, optionally shadow-tested. Shader: shaders/restir/initial_candidates.comp
#pragma once

#include "render/passes/lit_pass.h"

namespace engine::render {

class RestirInitialPass {
public:
    explicit RestirInitialPass(gpu::Context& ctx) : mPass(ctx, "restir_initial", "restir/initial_candidates", 4) {}
    struct Io {
        const gpu::Buffer& frameParams;   // read
        const gpu::Buffer& restirParams;  // read
        const gpu::Buffer& gbuffer;       // read
        gpu::Buffer& reservoirs;          // write
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, {&io.frameParams, &io.restirParams, &io.gbuffer, &io.reservoirs}, size);
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
