// ReSTIR spatial reuse (thesis §4.6): merges each pixel's own reservoir with the candidate
// reservoirs of k neighbours in an r-pixel disc. Shader: shaders/restir/spatial_reuse.comp
#pragma once

#include "render/passes/lit_pass.h"

namespace engine::render {

class RestirSpatialPass {
public:
    explicit RestirSpatialPass(gpu::Context& ctx) : mPass(ctx, "restir_spatial", "restir/spatial_reuse", 6) {}
    struct Io {
        const gpu::Buffer& frameParams;   // read
        const gpu::Buffer& restirParams;  // read
        const gpu::Buffer& gbuffer;       // read
        const gpu::Buffer& own;           // read: after temporal reuse, or the candidates
        const gpu::Buffer& candidates;    // read: what neighbours contribute
        gpu::Buffer& output;              // write
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, {&io.frameParams, &io.restirParams, &io.gbuffer, &io.own, &io.candidates, &io.output}, size);
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
