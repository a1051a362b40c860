// ReSTIR spatial reuse (thesis §4.6): merges each pixel's own reservoir with the candidate
// reservoirs of k neighbours in an r-pixel disc. Shader: shaders/restir/spatial_reuse.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/restir.h"

namespace engine::render {

struct RestirSpatialIo {
    const gpu::Buffer& frameParams;   // read
    const gpu::Buffer& restirParams;  // read
    const gpu::Buffer& gbuffer;       // read
    const gpu::Buffer& own;           // read: after temporal reuse, or the candidates
    const gpu::Buffer& candidates;    // read: what neighbours contribute
    gpu::Buffer& output;              // write
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::RESTIR_BINDING_FRAME, &frameParams},
                                           {shared::RESTIR_BINDING_PARAMS, &restirParams},
                                           {shared::RESTIR_BINDING_GBUFFER, &gbuffer},
                                           {shared::RESTIR_SPATIAL_BINDING_OWN, &own},
                                           {shared::RESTIR_SPATIAL_BINDING_CANDIDATES, &candidates},
                                           {shared::RESTIR_SPATIAL_BINDING_OUT, &output}});
    }
};

class RestirSpatialPass : public ScreenLitPass<RestirSpatialIo> {
public:
    using Io = RestirSpatialIo;
    explicit RestirSpatialPass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "restir_spatial", "restir/spatial_reuse") {}
};

}  // namespace engine::render
