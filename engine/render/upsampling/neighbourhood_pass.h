// Temporal upsampling's pre-pass, one dispatch over the render image: per render pixel, what the
// resolve needs of its 3x3 samples (their colour spread, their surface keys) and of its own
// (motion, edit flag), packed into UPSAMPLING_NEIGHBOURHOOD_TEXELS texels (shared/upsampling.h),
// so each display pixel reads those few texels instead of recomputing them from 21.
// Shader: shaders/upsampling/summarize_neighbourhood.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "shared/upsampling.h"

namespace engine::render {

struct NeighbourhoodIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: UpsamplingParams (the edited box)
    const gpu::Buffer& gbuffer;      // read (render size): motion, voxel
    const gpu::Buffer& radiance;     // read (render size)
    const gpu::Buffer& surfaceKeys;  // read (render size)
    gpu::Buffer& neighbourhood;      // write (render size)
    auto bindings() const {
        return std::to_array<PassBinding>(
            {{shared::NEIGHBOURHOOD_BINDING_FRAME, &frameParams},
             {shared::NEIGHBOURHOOD_BINDING_PARAMS, &params},
             {shared::NEIGHBOURHOOD_BINDING_GBUFFER, &gbuffer},
             {shared::NEIGHBOURHOOD_BINDING_RADIANCE, &radiance},
             {shared::NEIGHBOURHOOD_BINDING_SURFACE_KEYS, &surfaceKeys},
             {shared::NEIGHBOURHOOD_BINDING_OUT, &neighbourhood}});
    }
};

class NeighbourhoodPass : public ScreenPass<NeighbourhoodIo> {
public:
    using Io = NeighbourhoodIo;
    explicit NeighbourhoodPass(gpu::Context& ctx)
        : ScreenPass(ctx, "resolve.neighbourhood", "upsampling/summarize_neighbourhood") {}
};

}  // namespace engine::render
