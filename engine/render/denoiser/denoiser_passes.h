// The denoiser's dispatches: the temporal step, then edge-stopped a-trous passes, the last of
// which writes the denoised lighting back into the frame's radiance.
// Shaders: shaders/denoiser/temporal.comp, shaders/denoiser/atrous.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/denoiser.h"

namespace engine::render {

struct DenoiserTemporalIo {
    const gpu::Buffer& frameParams;      // read
    const gpu::Buffer& params;           // read: DenoiserParams
    const gpu::Buffer& gbuffer;          // read
    const gpu::Buffer& prevSurfaceKeys;  // read: last frame's
    const gpu::Buffer& radiance;         // read
    const gpu::Buffer& prevHistory;      // read
    gpu::Buffer& history;                // write
    const gpu::Buffer& prevMoments;      // read
    gpu::Buffer& moments;                // write
    gpu::Buffer& filtered;               // write: the a-trous passes' input
    auto bindings() const {
        return std::to_array<PassBinding>(
            {{shared::DENOISER_BINDING_FRAME, &frameParams},
             {shared::DENOISER_BINDING_PARAMS, &params},
             {shared::DENOISER_BINDING_GBUFFER, &gbuffer},
             {shared::DENOISER_BINDING_PREV_SURFACE_KEYS, &prevSurfaceKeys},
             {shared::DENOISER_BINDING_RADIANCE, &radiance},
             {shared::DENOISER_BINDING_PREV_HISTORY, &prevHistory},
             {shared::DENOISER_BINDING_HISTORY, &history},
             {shared::DENOISER_BINDING_PREV_MOMENTS, &prevMoments},
             {shared::DENOISER_BINDING_MOMENTS, &moments},
             {shared::DENOISER_BINDING_FILTERED, &filtered}});
    }
};

struct DenoiserAtrousIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: DenoiserParams (this pass's step, whether it is last)
    const gpu::Buffer& gbuffer;      // read (the last pass)
    gpu::Buffer& radiance;           // the last pass writes it
    const gpu::Buffer& input;        // read
    gpu::Buffer& output;             // write
    const gpu::Buffer& surfaceKeys;  // read
    auto bindings() const {
        return std::to_array<PassBinding>(
            {{shared::DENOISER_ATROUS_BINDING_FRAME, &frameParams},
             {shared::DENOISER_ATROUS_BINDING_PARAMS, &params},
             {shared::DENOISER_ATROUS_BINDING_GBUFFER, &gbuffer},
             {shared::DENOISER_ATROUS_BINDING_RADIANCE, &radiance},
             {shared::DENOISER_ATROUS_BINDING_INPUT, &input},
             {shared::DENOISER_ATROUS_BINDING_OUTPUT, &output},
             {shared::DENOISER_ATROUS_BINDING_SURFACE_KEYS, &surfaceKeys}});
    }
};

class DenoiserTemporalPass : public ScreenLitPass<DenoiserTemporalIo> {
public:
    using Io = DenoiserTemporalIo;
    explicit DenoiserTemporalPass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "denoise.temporal", "denoiser/temporal") {}
};

class DenoiserAtrousPass : public ScreenLitPass<DenoiserAtrousIo> {
public:
    using Io = DenoiserAtrousIo;
    explicit DenoiserAtrousPass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "denoise.atrous", "denoiser/atrous") {}
};

}  // namespace engine::render
