// Denoiser: the lighting of a real-time method (one ReSTIR sample per pixel, the cache's or the
// path tracer's indirect term, the sky) made smooth before the display's resolve
// (`--display denoised`). The albedo is divided out, the rest averaged over frames at the point
// each pixel's surface was (motion vectors; history kept only on the same voxel-face plane) and
// filtered in space by edge-stopped a-trous passes that never cross a voxel-face plane, then the
// albedo is multiplied back and the emission added: texture, emitters and the sky keep their
// edges. After Schied et al. 2017, "Spatiotemporal Variance-Guided Filtering", with the
// G-buffer's exact (voxel, face) identity where SVGF compares depth and normals. Runs after every
// term is added; an edit, a light, the sky or the settings changing restarts its history.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "render/denoiser/denoiser_passes.h"
#include "render/technique.h"

namespace engine::render {

class Denoiser : public Technique {
public:
    explicit Denoiser(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    void skip() override { mRestart = true; }

private:
    static constexpr std::uint32_t kMaxPasses = 6;

    gpu::Context& mCtx;
    DenoiserTemporalPass mTemporal;
    DenoiserAtrousPass mAtrous;
    // One parameter block per pass: the temporal step's, then each a-trous pass's.
    std::vector<gpu::Buffer> mParams;
    gpu::Buffer mHistory[2], mMoments[2], mFiltered[2];
    glm::uvec2 mSize{0};
    std::uint32_t mPasses = 0;
    bool mRestart = true;
};

}  // namespace engine::render
