#include "render/vct/voxel_cone_tracing.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/common.hpp>

namespace engine::render {

namespace {

// The union of two boxes (max exclusive); an empty box (min == max) adds nothing.
std::pair<glm::ivec3, glm::ivec3> unionOf(glm::ivec3 aMin, glm::ivec3 aMax, glm::ivec3 bMin, glm::ivec3 bMax) {
    if (aMin == aMax) return {bMin, bMax};
    if (bMin == bMax) return {aMin, aMax};
    return {glm::min(aMin, bMin), glm::max(aMax, bMax)};
}

}  // namespace

VoxelConeTracing::VoxelConeTracing(gpu::Context& ctx) : mCtx(ctx), mInject(ctx), mCones(ctx) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::VctParams), "vct.params");
}

std::uint64_t VoxelConeTracing::volumeBytes() {
    return std::uint64_t(shared::VCT_MAX_LEVELS) * shared::VCT_TEXELS_PER_LEVEL * shared::VCT_SLOTS * sizeof(glm::vec4);
}

glm::ivec3 VoxelConeTracing::levelOrigin(glm::vec3 position, std::uint32_t level) {
    const int texel = int(shared::VCT_BASE_TEXEL << level);
    const glm::ivec3 cameraTexel(glm::floor(position / float(texel)));
    return (cameraTexel - int(shared::VCT_RES / 2)) * texel;
}

void VoxelConeTracing::prepare(const lighting::LightingSettings& lighting, const Frame& frame, gpu::Uploader& uploader) {
    if (mVolumes[0].size() == 0) {
        mVolumes[0] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, volumeBytes(), "vct.volume0");
        mVolumes[1] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, volumeBytes(), "vct.volume1");
    }
    const std::uint32_t levels = std::clamp(lighting.vct.levels, 1u, shared::VCT_MAX_LEVELS);
    shared::VctParams p{};
    for (std::uint32_t l = 0; l < shared::VCT_MAX_LEVELS; ++l) {
        p.levelOrigin[l] = glm::ivec4(levelOrigin(frame.cameraPosition, l), int(shared::VCT_BASE_TEXEL << l));
        p.prevOrigin[l] = mPrevOrigins[l];
    }
    p.levels = levels;
    // Last frame's volume still holds this frame's light: nothing changed, the same settings.
    const bool previousValid = mPrepared && frame.frameIndex == mLastFrame + 1 && !frame.changed &&
                               mPrevSettings == lighting.vct && mPrevSeed == lighting.seed;
    p.flags = (lighting.vct.leakMitigation ? shared::VCT_LEAK_MITIGATION : 0u) |
              (lighting.vct.extraBounce ? shared::VCT_EXTRA_BOUNCE : 0u) | (previousValid ? shared::VCT_PREVIOUS_VALID : 0u);
    p.seed = lighting.seed;
    p.startOffset = lighting.vct.startOffset;
    // The objects' bounds now and last frame: where they are and where they left.
    const auto [dynamicMin, dynamicMax] = unionOf(frame.dynamicMin, frame.dynamicMax, mPrevDynamicMin, mPrevDynamicMax);
    p.dynamicMin = glm::ivec4(dynamicMin, 0);
    p.dynamicMax = glm::ivec4(dynamicMax, 0);
    p.refreshPeriod = std::max(lighting.vct.refreshPeriod, 1u);
    p.frame = frame.frameIndex;
    uploader.write(mParams, 0, &p, sizeof(p));
    for (std::uint32_t l = 0; l < shared::VCT_MAX_LEVELS; ++l) mPrevOrigins[l] = p.levelOrigin[l];
    mPrevDynamicMin = frame.dynamicMin;
    mPrevDynamicMax = frame.dynamicMax;
    mPrevSettings = lighting.vct;
    mPrevSeed = lighting.seed;
    mLevels = levels;
    mLastFrame = frame.frameIndex;
    mPrepared = true;
}

void VoxelConeTracing::record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io, glm::uvec2 size) {
    gpu::Buffer& volume = mVolumes[mCurrent];
    mInject.record(cmd, scene, {io.frameParams, mParams, mVolumes[mCurrent ^ 1u], volume}, mLevels);
    mCones.record(cmd, scene, {io.frameParams, mParams, io.gbuffer, volume, io.indirect, io.radiance}, size);
    mCurrent ^= 1u;
}

}  // namespace engine::render
