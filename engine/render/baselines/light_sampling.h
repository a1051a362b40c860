// LightSampling: the light-sampling baselines (`--method uniform`: N light samples with N shadow
// rays per pixel; `--method bruteforce`: every light once). One pass over the G-buffer, run once
// per range of the emitters or samples that fits lavapipe's loop budget (render/loop_budget.h).
#pragma once

#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "render/baselines/light_sampling_pass.h"
#include "render/technique.h"

namespace engine::render {

class LightSampling : public Technique {
public:
    explicit LightSampling(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;

private:
    gpu::Context& mCtx;
    LightSamplingPass mPass;
    std::vector<gpu::Buffer> mParams;  // one per dispatch of this frame (at least as many)
    std::uint32_t mDispatches = 1;
    gpu::Buffer mPartial;  // the running sums, when a frame takes more than one dispatch
};

}  // namespace engine::render
