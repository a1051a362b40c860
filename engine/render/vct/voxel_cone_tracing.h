// VoxelConeTracing: the leaky indirect term meant to be cheap (`--indirect vct`; the Wicked
// Engine's voxel GI, after Crassin et al. 2011). A clipmap centred on the camera (kept over the
// world) of up to four 32^3 levels, texels 2-16 voxels wide, injected from direct light (those that
// stay in view in turn, and only those with an occupied cell: shaders/vct/classify_texels.comp
// lists them for inject_radiance.comp, over the blocks of texels the host lists in
// vct_block_list.h — a still view of a world at rest classifies nothing), then six diffuse cones
// per pixel from the G-buffer's surface (trace_cones.comp). A clipmap rather than sparse bricks:
// its memory is fixed (4 x 32^3 texels x 6 directions x 16 bytes = 12 MiB per volume, two with the
// extra bounce's previous frame) whatever the world's size, and a cone reads it with plain index
// arithmetic — no page table walk per sample; the price is resolution far from the camera, which is
// where cones are wide. Owns the volumes: one updated in place, or with the extra bounce two
// ping-ponged (the bounce reads the last frame's while this frame's is written, and unchanged
// texels are copied across).
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "gpu/buffer.h"
#include "gpu/uploader.h"
#include "lighting/lighting_settings.h"
#include "render/technique.h"
#include "render/vct/vct_block_list.h"
#include "render/vct/vct_passes.h"

namespace engine::render {

// Runs with `--indirect vct` beside any method but the reference (lighting::usesVct).
class VoxelConeTracing : public Technique {
public:
    explicit VoxelConeTracing(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    // Every texel is re-injected when the static world, the lights or the sky changed; texels
    // near the objects' bounds, now and last frame, always; the others in turn while that can
    // change them (the objects changed in the last refreshPeriod frames, or the extra bounce).
    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    void collect(FrameResult& result) override;

    // Level l's minimum corner (voxels) for a camera at `position` in a world whose solid part
    // lies in [worldMin, worldMax): centred on the camera, moved along each axis the least way
    // that covers as much of that box as the level holds (the whole box where the level is
    // wider), then snapped to its texel of VCT_BASE_TEXEL << l voxels. A camera inside the box
    // stays inside every level; one outside it (Cornell's, 380 voxels before the box) no longer
    // leaves the world out of the clipmap.
    static glm::ivec3 levelOrigin(glm::vec3 position, std::uint32_t level, glm::ivec3 worldMin,
                                  glm::ivec3 worldMax);
    static std::uint64_t volumeBytes();

private:
    gpu::Context& mCtx;
    VctInjectPass mInject;
    VctConesPass mCones;
    gpu::Buffer mParams;
    gpu::Buffer mList;    // the texels vct.inject lights this frame (VctInjectPass)
    gpu::Buffer mBlocks;  // the blocks of texels vct.classify visits this frame
    VctBlockList mBlockList;
    std::uint32_t mBlockCount = 0;
    double mPrepareMs = 0.0;
    std::array<gpu::Buffer, 2> mVolumes;
    std::uint32_t mCurrent = 0, mLevels = 0;
    bool mExtraBounce = false;  // this frame's: the volumes ping-pong only with the extra bounce
    bool mPrepared = false;     // a volume was injected, in frame mLastFrame
    std::uint32_t mLastFrame = 0;
    lighting::VctSettings mPrevSettings;
    std::uint32_t mPrevSeed = 0;
    std::array<glm::ivec4, 4> mPrevOrigins{}, mPrevPrevOrigins{};  // last frame's, the one's before
    glm::ivec3 mPrevDynamicMin{0}, mPrevDynamicMax{0}, mPrevPrevDynamicMin{0},
        mPrevPrevDynamicMax{0};
    bool mPreviousWasValid = false;          // last frame's VCT_PREVIOUS_VALID
    std::uint64_t mGridVersion = 0;          // changes with the static world (VctBlockList's cache)
    bool mObjectsChanging = false;           // the objects changed since the last full injection,
    std::uint32_t mObjectsChangedFrame = 0;  // last in this frame
};

}  // namespace engine::render
