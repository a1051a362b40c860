// Reference path tracer: adds samples to a running sum per pixel and writes the mean. It traces
// its own camera rays (box-filtered pixels), so it does not read the G-buffer.
// Shader: shaders/reference/path_trace.comp
#pragma once

#include "render/passes/lit_pass.h"
#include "shared/reference.h"

namespace engine::render {

struct ReferenceIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: ReferenceParams
    gpu::Buffer& accumulation;       // read and write
    gpu::Buffer& radiance;           // write
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::REFERENCE_BINDING_FRAME, &frameParams},
                                           {shared::REFERENCE_BINDING_PARAMS, &params},
                                           {shared::REFERENCE_BINDING_ACCUMULATION, &accumulation},
                                           {shared::REFERENCE_BINDING_RADIANCE, &radiance}});
    }
};

class ReferencePass : public ScreenLitPass<ReferenceIo> {
public:
    using Io = ReferenceIo;
    explicit ReferencePass(gpu::Context& ctx)
        : ScreenLitPass(ctx, "reference", "reference/path_trace") {}
};

}  // namespace engine::render
