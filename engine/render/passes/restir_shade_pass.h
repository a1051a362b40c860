// Shading of the reservoir methods: emission + sun + the reservoir's light with one shadow ray.
// Shader: shaders/restir/shade.comp
#pragma once

#include "render/passes/lit_pass.h"

namespace engine::render {

class RestirShadePass {
public:
    explicit RestirShadePass(gpu::Context& ctx) : mPass(ctx, "restir_shade", "restir/shade", 5) {}
    struct Io {
        const gpu::Buffer& frameParams;   // read
        const gpu::Buffer& restirParams;  // read
        const gpu::Buffer& gbuffer;       // read
        gpu::Buffer& reservoirs;          // read; occluded samples lose their weight
        gpu::Buffer& radiance;            // write
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
        mPass.record(cmd, scene, {&io.frameParams, &io.restirParams, &io.gbuffer, &io.reservoirs, &io.radiance}, size);
    }

private:
    LitPass mPass;
};

}  // namespace engine::render
