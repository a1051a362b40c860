// PathIndirect: the real-time path-traced indirect term (`--indirect path`), the baseline the
// irradiance cache is measured against at equal time (vox bench flythrough, docs/ACCURACY.md).
// Per pixel and frame, `samples` bounce paths from the G-buffer's surface (the reference path
// tracer's walk from the first bounce on), averaged over frames while camera and world stay still
// and restarted when either changes — on a flythrough every frame starts afresh.
// Owns the running sum and the parameters. A frame's paths run as several dispatches when their
// loops would spend more than lavapipe's loop budget (render/loop_budget.h); each path's random
// numbers follow from its index in the frame, so the split changes no bit.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/uploader.h"
#include "lighting/lighting_settings.h"
#include "render/path_indirect/path_indirect_pass.h"
#include "render/technique.h"

namespace engine::render {

// Runs with `--indirect path` beside any method but the reference (lighting::usesPath).
class PathIndirect : public Technique {
public:
    explicit PathIndirect(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    // Restarts the running sum when the camera moved, the world changed or the history is gone.
    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;

    // Paths per pixel in the running sum after the last prepared frame.

private:
    gpu::Context& mCtx;
    PathIndirectPass mPass;
    // One PathIndirectParams per dispatch of this frame (at least as many): a frame's paths are
    // split into dispatches that fit lavapipe's loop budget (render/loop_budget.h).
    std::vector<gpu::Buffer> mParams;
    std::uint32_t mDispatches = 1;
    gpu::Buffer mAccumulation;
    glm::uvec2 mSize{0};
    std::uint32_t mPaths = 0;
};

}  // namespace engine::render
