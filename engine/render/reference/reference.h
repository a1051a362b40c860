// Reference: the progressive path tracer (`--method reference`; `--indirect reference` makes it
// the method with bounces), the ground truth the other methods are measured against. Owns the
// running sum per pixel, which restarts when the view, the world or the settings change. A
// frame's samples run as several dispatches when their loops would spend more than lavapipe's
// loop budget (render/loop_budget.h); each sample's random numbers follow from the pixel's sample
// count, so the split changes no bit of the sum.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "render/reference/reference_pass.h"
#include "render/technique.h"

namespace engine::render {

class Reference : public Technique {
public:
    explicit Reference(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    void collect(FrameResult& result) override;
    void skip() override { mSamples = 0; }

private:
    gpu::Context& mCtx;
    ReferencePass mPass;
    // One ReferenceParams per dispatch of this frame (at least as many): a frame's samples are
    // split into dispatches that fit lavapipe's loop budget (render/loop_budget.h).
    std::vector<gpu::Buffer> mParams;
    std::uint32_t mDispatches = 1;
    gpu::Buffer mAccumulation;
    glm::uvec2 mSize{0};
    bool mRestart = true;        // this frame clears the running sum
    std::uint32_t mSamples = 0;  // samples per pixel in the running sum after this frame
};

}  // namespace engine::render
