// ReSTIR temporal reuse (thesis §4.4, §4.9): merges this frame's candidate reservoirs with last
// frame's final ones at the motion-vector pixel into each pixel's own reservoir.
// Shader: shaders/restir/temporal_reuse.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/restir.h"

namespace engine::render {

struct RestirTemporalIo {
    const gpu::Buffer& frameParams;     // read
    const gpu::Buffer& restirParams;    // read
    const gpu::Buffer& gbuffer;         // read
    const gpu::Buffer& prevGbuffer;     // read
    const gpu::Buffer& candidates;      // read
    const gpu::Buffer& prevReservoirs;  // read
    gpu::Buffer& own;                   // write
    auto bindings() const {
        return std::to_array<PassBinding>(
            {{shared::RESTIR_BINDING_FRAME, &frameParams},
             {shared::RESTIR_BINDING_PARAMS, &restirParams},
             {shared::RESTIR_BINDING_GBUFFER, &gbuffer},
             {shared::RESTIR_TEMPORAL_BINDING_PREV_GBUFFER, &prevGbuffer},
             {shared::RESTIR_TEMPORAL_BINDING_CANDIDATES, &candidates},
             {shared::RESTIR_TEMPORAL_BINDING_PREVIOUS, &prevReservoirs},
             {shared::RESTIR_TEMPORAL_BINDING_OWN, &own}});
    }
};

class RestirTemporalPass : public ScreenLitPass<RestirTemporalIo> {
public:
    using Io = RestirTemporalIo;
    explicit RestirTemporalPass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "restir_temporal", "restir/temporal_reuse") {}
};

}  // namespace engine::render
