// Temporal accumulation's one dispatch: the running mean of the radiance into the history, and
// the mean back into the radiance. Shader: shaders/accumulation/accumulate.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "shared/accumulation.h"

namespace engine::render {

struct AccumulationIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: AccumulationParams
    gpu::Buffer& history;            // read and write: the mean so far
    gpu::Buffer& radiance;           // read and write: this frame's, replaced by the mean
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::ACCUMULATION_BINDING_FRAME, &frameParams},
                                           {shared::ACCUMULATION_BINDING_PARAMS, &params},
                                           {shared::ACCUMULATION_BINDING_HISTORY, &history},
                                           {shared::ACCUMULATION_BINDING_RADIANCE, &radiance}});
    }
};

class AccumulationPass : public ScreenPass<AccumulationIo> {
public:
    using Io = AccumulationIo;
    explicit AccumulationPass(gpu::Context& ctx)
        : ScreenPass(ctx, "accumulate", "accumulation/accumulate") {}
};

}  // namespace engine::render
