// Accumulation: the lit image averaged over the frames in which nothing it depends on changed
// (`--accumulate on`): the camera, the world, the lights, the sky and the settings. Runs after
// every other technique, so the mean covers direct light and every term added to it; a moving
// camera or an edit restarts it from that frame (FrameChanges::restartsAccumulation). The
// stochastic methods' per-pixel noise falls as 1/sqrt(frames) while the view rests; their mean
// is unchanged. Owns the history.
#pragma once

#include <cstdint>
#include <string>

#include "gpu/buffer.h"
#include "render/accumulation/accumulation_pass.h"
#include "render/technique.h"

namespace engine::render {

class Accumulation : public Technique {
public:
    explicit Accumulation(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    void collect(FrameResult& result) override;
    void skip() override { mFrames = 0; }

private:
    gpu::Context& mCtx;
    AccumulationPass mPass;
    gpu::Buffer mParams, mHistory;
    glm::uvec2 mSize{0};
    std::uint32_t mFrames = 0;  // frames since the last restart, this one included
};

}  // namespace engine::render
