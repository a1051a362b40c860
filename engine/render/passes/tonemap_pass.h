// Tonemapping: linear radiance -> exposure -> ACES fit -> sRGB RGBA8. Shader:
// shaders/post/tonemap.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "shared/bindings.h"

namespace engine::render {

struct TonemapIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& radiance;     // read
    gpu::Buffer& ldr;                // write: packed RGBA8 per pixel
    const gpu::Buffer& exposure;     // read: ExposureState, when FrameParams.exposure.y is 1
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::TONEMAP_BINDING_FRAME, &frameParams},
                                           {shared::TONEMAP_BINDING_RADIANCE, &radiance},
                                           {shared::TONEMAP_BINDING_LDR, &ldr},
                                           {shared::TONEMAP_BINDING_EXPOSURE, &exposure}});
    }
};

class TonemapPass : public ScreenPass<TonemapIo> {
public:
    using Io = TonemapIo;
    explicit TonemapPass(gpu::Context& ctx) : ScreenPass(ctx, "tonemap", "post/tonemap") {}
};

}  // namespace engine::render
