// Tonemapping: linear radiance -> exposure -> ACES fit -> sRGB RGBA8. Shader: shaders/post/tonemap.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "shared/bindings.h"

namespace engine::render {

class TonemapPass {
public:
    struct Io {
        const gpu::Buffer& frameParams;  // read
        const gpu::Buffer& radiance;     // read
        gpu::Buffer& ldr;                // write: packed RGBA8 per pixel
        auto bindings() const {
            return std::to_array<PassBinding>({{shared::TONEMAP_BINDING_FRAME, &frameParams},
                                               {shared::TONEMAP_BINDING_RADIANCE, &radiance},
                                               {shared::TONEMAP_BINDING_LDR, &ldr}});
        }
    };
    explicit TonemapPass(gpu::Context& ctx) : mPass(ctx, "tonemap", "post/tonemap", bindingCount<Io>()) {}
    void record(gpu::CommandList& cmd, const Io& io, glm::uvec2 size) { mPass.record(cmd, io.bindings(), screenGroups(size)); }

private:
    ComputePass mPass;
};

}  // namespace engine::render
