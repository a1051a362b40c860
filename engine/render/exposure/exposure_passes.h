// Automatic exposure's two dispatches over one set of buffers: the histogram of the lit image's
// log2 luminance, then one invocation that meters it and adapts the exposure in use.
// Shaders: shaders/exposure/histogram.comp, shaders/exposure/adapt.comp
#pragma once

#include "render/passes/compute_pass.h"
#include "shared/exposure.h"

namespace engine::render {

struct ExposureIo {
    const gpu::Buffer& frameParams;  // read
    const gpu::Buffer& params;       // read: ExposureParams
    const gpu::Buffer& radiance;     // read
    gpu::Buffer& histogram;          // histogram: written; adapt: read
    gpu::Buffer& state;              // adapt: read and written (ExposureState)
    auto bindings() const {
        return std::to_array<PassBinding>({{shared::EXPOSURE_BINDING_FRAME, &frameParams},
                                           {shared::EXPOSURE_BINDING_PARAMS, &params},
                                           {shared::EXPOSURE_BINDING_RADIANCE, &radiance},
                                           {shared::EXPOSURE_BINDING_HISTOGRAM, &histogram},
                                           {shared::EXPOSURE_BINDING_STATE, &state}});
    }
};

class ExposureHistogramPass : public ScreenPass<ExposureIo> {
public:
    explicit ExposureHistogramPass(gpu::Context& ctx)
        : ScreenPass(ctx, "exposure.histogram", "exposure/histogram") {}
};

class ExposureAdaptPass {
public:
    explicit ExposureAdaptPass(gpu::Context& ctx)
        : mPass(ctx, "exposure.adapt", "exposure/adapt", bindingCount<ExposureIo>()) {}
    void record(gpu::CommandList& cmd, const ExposureIo& io) {
        mPass.record(cmd, io.bindings(), glm::uvec2(1));
    }

private:
    ComputePass mPass;
};

}  // namespace engine::render
