// ReSTIR initial candidates (thesis §4.4-4.5): M light samples per pixel resampled into one
// reservoir, optionally shadow-tested. Shader: shaders/restir/initial_candidates.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/restir.h"

namespace engine::render {

struct RestirInitialIo {
    const gpu::Buffer& frameParams;   // read
    const gpu::Buffer& restirParams;  // read
    const gpu::Buffer& gbuffer;       // read
    gpu::Buffer& reservoirs;          // write
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::RESTIR_BINDING_FRAME, &frameParams},
                                           {shared::RESTIR_BINDING_PARAMS, &restirParams},
                                           {shared::RESTIR_BINDING_GBUFFER, &gbuffer},
                                           {shared::RESTIR_INITIAL_BINDING_OUT, &reservoirs}});
    }
};

class RestirInitialPass : public ScreenLitPass<RestirInitialIo> {
public:
    using Io = RestirInitialIo;
    explicit RestirInitialPass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "restir_initial", "restir/initial_candidates") {}
};

}  // namespace engine::render
