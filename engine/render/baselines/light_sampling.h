// LightSampling: the light-sampling baselines (`--method uniform`: N light samples with N shadow
// rays per pixel; `--method bruteforce`: every light once). One pass over the G-buffer.
#pragma once

#include <string>

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
    LightSamplingPass mPass;
    gpu::Buffer mParams;
};

}  // namespace engine::render
