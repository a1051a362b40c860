// Reference path tracer: adds samples to a running sum per pixel and writes the mean. It traces
// its own camera rays (box-filtered pixels), so it does not read the G-buffer.
// Shader: shaders/reference/path_trace.comp
#pragma once

#include "render/passes/lit_pass.h"

namespace engine::render {

class ReferencePass {
public:
    explicit ReferencePass(gpu::Context& ctx) : mPass(ctx, "reference", "reference/path_trace", 4) {}
    struct Io {
        const gpu::Buffer& frameParams;   // read
        const gpu::Buffer& restirParams;  // read
        gpu::Buffer& accumulation;        // read and write
        gpu::Buffer& radiance;            // write
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, {&io.frameParams, &io.restirParams, &io.accumulation, &io.radiance}, size);
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
