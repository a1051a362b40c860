// Temporal upsampling's dispatch over the display: this frame's jittered samples and the display
// history resolved into the display image (after NeighbourhoodPass summarised the samples), and
// that image tonemapped (the shown one: the frame's tonemap pass does not run). Shader:
// shaders/upsampling/resolve.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "shared/upsampling.h"

namespace engine::render {

struct ResolveIo {
    const gpu::Buffer& frameParams;    // read
    const gpu::Buffer& params;         // read: UpsamplingParams
    const gpu::Buffer& neighbourhood;  // read (render size): NeighbourhoodPass's summary
    const gpu::Buffer& surfaceKeys;    // read (render size): where a summary holds too many keys
    const gpu::Buffer& radiance;       // read (render size)
    const gpu::Buffer& prevDisplay;    // read
    gpu::Buffer& display;              // write
    const gpu::Buffer& prevKeys;       // read
    gpu::Buffer& keys;                 // write
    const gpu::Buffer& exposure;       // read: ExposureState, when FrameParams.exposure.y is 1
    gpu::Buffer& ldr;                  // write: the display tonemapped, packed RGBA8 per pixel
    auto bindings() const {
        return std::to_array<PassBinding>(
            {{shared::UPSAMPLING_BINDING_FRAME, &frameParams},
             {shared::UPSAMPLING_BINDING_PARAMS, &params},
             {shared::UPSAMPLING_BINDING_NEIGHBOURHOOD, &neighbourhood},
             {shared::UPSAMPLING_BINDING_RADIANCE, &radiance},
             {shared::UPSAMPLING_BINDING_PREV_DISPLAY, &prevDisplay},
             {shared::UPSAMPLING_BINDING_DISPLAY, &display},
             {shared::UPSAMPLING_BINDING_PREV_KEYS, &prevKeys},
             {shared::UPSAMPLING_BINDING_KEYS, &keys},
             {shared::UPSAMPLING_BINDING_SURFACE_KEYS, &surfaceKeys},
             {shared::UPSAMPLING_BINDING_EXPOSURE, &exposure},
             {shared::UPSAMPLING_BINDING_LDR, &ldr}});
    }
};

class ResolvePass : public ScreenPass<ResolveIo> {
public:
    using Io = ResolveIo;
    explicit ResolvePass(gpu::Context& ctx) : ScreenPass(ctx, "resolve", "upsampling/resolve") {}
};

}  // namespace engine::render
