// AutoExposure: the exposure follows the lit image (`--auto-exposure on`), metered from a
// histogram of its log2 luminance on the GPU and adapted a fraction of the way per frame, so a
// scene with indirect or sky light is not washed out by an exposure set for direct light alone,
// and a dark one is not black. Deterministic: integer histogram counts, adaptation per frame
// (not per second). Runs last, on what the display shows; the EXR stays linear, before exposure.
// The exposure in use lives in the frame's exposure state (FrameBuffers::exposure), which the
// tonemap reads when FrameParams.exposure.y says auto.
#pragma once

#include <string>

#include "gpu/buffer.h"
#include "render/exposure/exposure_passes.h"
#include "render/technique.h"

namespace engine::render {

class AutoExposure : public Technique {
public:
    explicit AutoExposure(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    void skip() override { mRestart = true; }

private:
    ExposureHistogramPass mHistogramPass;
    ExposureAdaptPass mAdaptPass;
    gpu::Buffer mParams, mHistogram;
    bool mRestart = true;      // the next frame takes the metered exposure at once
    bool mClearState = false;  // this frame does: the state starts from zero
};

}  // namespace engine::render
