// Reference path tracer: adds samples to a running sum per pixel and writes the mean.
// Shader: shaders/reference/path_trace.comp
#pragma once

#include "render/passes/lit_pass.h"

namespace engine::render {

class ReferencePass {
public:
    explicit ReferencePass(gpu::Context& ctx) : mPass(ctx, "reference", "reference/path_trace", 5) {}
    struct Io {
        const gpu::Buffer& frameParams;   // read
        const gpu::Buffer& restirParams;  // read
        const gpu::Buffer& gbuffer;       // read
        gpu::Buffer& accumulation;        // read and write
        gpu::Buffer& radiance;            // write
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, {&io.frameParams, &io.restirParams, &io.gbuffer, &io.accumulation, &io.radiance}, size);
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
