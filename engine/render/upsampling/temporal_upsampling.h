// TemporalUpsampling: the displayed image at the display's size from the lighting at the render
// size (`--display upsampled` or `denoised`). Each frame moves the primary rays by a sub-pixel
// jitter (Halton 2,3: a cycle of 16 to 128 offsets, jitterPhases); the resolve
// (shaders/upsampling/resolve.comp) blends this frame's samples into last frame's display image,
// reprojected by the G-buffer's exact motion (the camera, and each object's own transform),
// dropped where its voxel-face plane is not among this frame's nearby ones and clipped to their
// colour spread elsewhere. A still camera converges to an anti-aliased image; a change of render
// size keeps the display's history. The display image is the renderer's (FrameBuffers::display),
// and so is the shown image the resolve tonemaps into (FrameBuffers::ldr): the readback and the
// presenter take them from there. Before the resolve, a pre-pass per render pixel
// (shaders/upsampling/summarize_neighbourhood.comp) summarises each sample's 3x3 neighbourhood,
// which every display pixel it is nearest to would otherwise gather again.
#pragma once

#include <cstdint>
#include <string>

#include "gpu/buffer.h"
#include "render/technique.h"
#include "render/upsampling/neighbourhood_pass.h"
#include "render/upsampling/resolve_pass.h"

namespace engine::render {

// Device bytes of the pre-pass's summary per render pixel.
inline constexpr std::uint64_t kNeighbourhoodBytesPerPixel =
    shared::UPSAMPLING_NEIGHBOURHOOD_TEXELS * sizeof(glm::uvec4);

// Halton (2, 3) point `index` (from 1) minus 0.5: a sub-pixel offset in (-0.5, 0.5)^2.
glm::vec2 jitterOffset(std::uint32_t index);

// Jitter offsets in a cycle: 8 per display pixel a render pixel covers, as AMD FSR 2's
// ffxFsr2GetJitterPhaseCount (8 x (display / render)^2), 16 to 128. At scale 0.5 a cycle of 16
// put only 4 distinct points in each display pixel, so a still image stopped converging at its
// edges after 16 frames; 32 put 8 there. At the display's own size it stays 16.
std::uint32_t jitterPhases(glm::uvec2 render, glm::uvec2 display);

class TemporalUpsampling : public Technique {
public:
    explicit TemporalUpsampling(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    void skip() override;
    // The pre-pass's summary of the last frame (shared/upsampling.h), for tests.
    const gpu::Buffer& neighbourhood() const { return mNeighbourhood; }

private:
    gpu::Context& mCtx;
    NeighbourhoodPass mNeighbourhoodPass;
    ResolvePass mPass;
    gpu::Buffer mParams;
    gpu::Buffer mNeighbourhood;  // the pre-pass's summary per render pixel
    glm::uvec2 mRenderSize{0};
    gpu::Buffer mKeys[2];
    glm::uvec2 mDisplaySize{0};
    glm::vec2 mPrevJitter{0.0f};  // the last frame's jitter (its G-buffer's samples)
    bool mRestart = true;
    std::uint32_t mStillFrames = 0;  // frames in a row with the camera and the world unchanged
};

}  // namespace engine::render
