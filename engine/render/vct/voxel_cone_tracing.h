// VoxelConeTracing: the leaky indirect term meant to be cheap (`--indirect vct`; the Wicked
// Engine's voxel GI, after Crassin et al. 2011). A camera-centred clipmap of up to four 32^3
// levels, texels 2-16 voxels wide, injected from direct light (those that stay in view in
// turn; shaders/vct/inject_radiance.comp), then six diffuse cones per pixel from the G-buffer's
// surface (trace_cones.comp). A clipmap rather than sparse bricks: its memory is fixed (4 x 32^3 texels
// x 6 directions x 16 bytes = 12 MiB per volume, two with the extra bounce's previous frame)
// whatever the world's size, and a cone reads it with plain index arithmetic — no page table
// walk per sample; the price is resolution far from the camera, which is where cones are wide.
// Owns the volumes (ping-ponged: unchanged texels and the extra bounce read the last frame's).
// Each frame: prepare() (before the frame's uploads are recorded), then record() after the
// direct lighting.
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "gpu/uploader.h"
#include "lighting/lighting_settings.h"
#include "render/vct/vct_passes.h"

namespace engine::render {

class VoxelConeTracing {
public:
    explicit VoxelConeTracing(gpu::Context& ctx);

    // `changed`: the static world, the lights or the sky changed (every texel is re-injected).
    // `dynamicMin/Max`: the dynamic objects' bounds in voxels (max exclusive; empty if min >= max).
    struct Frame {
        glm::vec3 cameraPosition{0.0f};
        std::uint32_t frameIndex = 0;
        bool changed = true;
        glm::ivec3 dynamicMin{0}, dynamicMax{0};
    };
    void prepare(const lighting::LightingSettings& lighting, const Frame& frame, gpu::Uploader& uploader);
    struct Io {
        const gpu::Buffer& frameParams;  // read
        const gpu::Buffer& gbuffer;      // read
        gpu::Buffer& radiance;           // the term is added
        gpu::Buffer& indirect;           // write: the term alone
    };
    void record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size);

    // Level l's minimum corner (voxels) for a camera at `position`: the camera's texel, snapped,
    // minus half the level; its texel is VCT_BASE_TEXEL << l voxels.
    static glm::ivec3 levelOrigin(glm::vec3 position, std::uint32_t level);
    static std::uint64_t volumeBytes();

private:
    gpu::Context& mCtx;
    VctInjectPass mInject;
    VctConesPass mCones;
    gpu::Buffer mParams;
    std::array<gpu::Buffer, 2> mVolumes;
    std::uint32_t mCurrent = 0, mLevels = 0;
    bool mPrepared = false;  // a volume was injected, in frame mLastFrame
    std::uint32_t mLastFrame = 0;
    lighting::VctSettings mPrevSettings;
    std::uint32_t mPrevSeed = 0;
    std::array<glm::ivec4, 4> mPrevOrigins{};
    glm::ivec3 mPrevDynamicMin{0}, mPrevDynamicMax{0};
};

}  // namespace engine::render
