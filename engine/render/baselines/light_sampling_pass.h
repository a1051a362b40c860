// Light-sampling baselines: N light samples with N shadow rays per pixel, or every light once
// (one dispatch per range of emitters or samples, LightSampling::record).
// Shader: shaders/baselines/light_sampling.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/light_sampling.h"

namespace engine::render {

struct LightSamplingIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: LightSamplingParams
    const gpu::Buffer& gbuffer;      // read
    gpu::Buffer& radiance;           // write
    gpu::Buffer& partial;            // read and write: the sums between a frame's dispatches
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::LIGHT_SAMPLING_BINDING_FRAME, &frameParams},
                                           {shared::LIGHT_SAMPLING_BINDING_PARAMS, &params},
                                           {shared::LIGHT_SAMPLING_BINDING_GBUFFER, &gbuffer},
                                           {shared::LIGHT_SAMPLING_BINDING_RADIANCE, &radiance},
                                           {shared::LIGHT_SAMPLING_BINDING_PARTIAL, &partial}});
    }
};

class LightSamplingPass : public ScreenLitPass<LightSamplingIo> {
public:
    using Io = LightSamplingIo;
    explicit LightSamplingPass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "light_sampling", "baselines/light_sampling") {}
};

}  // namespace engine::render
