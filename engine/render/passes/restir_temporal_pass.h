// ReSTIR temporal reuse (thesis §4.4, §4.9): merges this frame's candidate reservoirs with last
// frame's final ones at the motion-vector pixel into each pixel's own reservoir.
// Shader: shaders/restir/temporal_reuse.comp
#pragma once

#include "render/passes/lit_pass.h"

namespace engine::render {

class RestirTemporalPass {
public:
    explicit RestirTemporalPass(gpu::Context& ctx) : mPass(ctx, "restir_temporal", "restir/temporal_reuse", 7) {}
    struct Io {
        const gpu::Buffer& frameParams;     // read
        const gpu::Buffer& restirParams;    // read
        const gpu::Buffer& gbuffer;         // read
        const gpu::Buffer& prevGbuffer;     // read
        const gpu::Buffer& candidates;      // read
        const gpu::Buffer& prevReservoirs;  // read
        gpu::Buffer& own;                   // write
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, {&io.frameParams, &io.restirParams, &io.gbuffer, &io.prevGbuffer, &io.candidates, &io.prevReservoirs, &io.own}, size);
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
