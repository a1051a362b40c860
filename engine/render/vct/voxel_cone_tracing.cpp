#include "render/vct/voxel_cone_tracing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <utility>

#include "render/frame_commands.h"
#include "render/frame_result.h"

namespace engine::render {

namespace {

// The union of two boxes (max exclusive); an empty box (min == max) adds nothing.
std::pair<glm::ivec3, glm::ivec3> unionOf(glm::ivec3 aMin, glm::ivec3 aMax, glm::ivec3 bMin,
                                          glm::ivec3 bMax) {
    if (aMin == aMax) return {bMin, bMax};
    if (bMin == bMax) return {aMin, aMax};
    return {glm::min(aMin, bMin), glm::max(aMax, bMax)};
}

}  // namespace

VoxelConeTracing::VoxelConeTracing(gpu::Context& ctx) : mCtx(ctx), mInject(ctx), mCones(ctx) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::VctParams), "vct.params");
    mList = gpu::Buffer(ctx, gpu::BufferKind::Storage, VctInjectPass::listBytes(), "vct.list");
    mBlocks =
        gpu::Buffer(ctx, gpu::BufferKind::Storage, VctInjectPass::blocksBytes(), "vct.blocks");
}

std::uint64_t VoxelConeTracing::volumeBytes() {
    return std::uint64_t(shared::VCT_MAX_LEVELS) * shared::VCT_TEXELS_PER_LEVEL *
           shared::VCT_SLOTS * sizeof(glm::vec4);
}

glm::ivec3 VoxelConeTracing::levelOrigin(glm::vec3 position, std::uint32_t level,
                                         glm::ivec3 worldMin, glm::ivec3 worldMax) {
    const int texel = int(shared::VCT_BASE_TEXEL << level);
    const float half = float(shared::VCT_RES / 2 * std::uint32_t(texel));
    // Texels outside the world are empty, as the sky past the clipmap is: moving the level over
    // the world loses nothing and gains the surfaces a camera-centred level would leave out.
    glm::vec3 centre = position;
    for (int a = 0; a < 3; ++a) {
        const float lo = float(worldMin[a]) + half, hi = float(worldMax[a]) - half;
        centre[a] =
            lo <= hi ? std::clamp(position[a], lo, hi) : 0.5f * float(worldMin[a] + worldMax[a]);
    }
    const glm::ivec3 centreTexel(glm::floor(centre / float(texel)));
    return (centreTexel - int(shared::VCT_RES / 2)) * texel;
}

TechniquePlan VoxelConeTracing::plan(const lighting::LightingSettings& l, const SceneShape&,
                                     glm::uvec2) {
    TechniquePlan p;
    p.runs = lighting::usesVct(l);
    p.addsIndirect = true;
    p.deviceBytes = sizeof(shared::VctParams) + 2 * volumeBytes() +  // fixed: two volumes
                    VctInjectPass::listBytes() + VctInjectPass::blocksBytes();
    return p;
}

std::string VoxelConeTracing::describe(const lighting::LightingSettings& l) {
    const lighting::VctSettings& v = l.vct;
    return fmt::format("vct {} level(s) refresh 1/{}{}{}", v.levels, v.refreshPeriod,
                       v.leakMitigation
                           ? fmt::format(" leak mitigation (offset {:g})", v.startOffset)
                           : " no leak mitigation",
                       v.extraBounce ? " extra bounce" : "");
}

void VoxelConeTracing::prepare(const FrameChanges& changes, const FrameInput& in,
                               gpu::Uploader& uploader, shared::FrameParams&) {
    const auto start = std::chrono::steady_clock::now();
    const lighting::LightingSettings& lighting = in.lighting;
    if (mVolumes[0].size() == 0) {
        mVolumes[0] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, volumeBytes(), "vct.volume0");
        mVolumes[1] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, volumeBytes(), "vct.volume1");
    }
    // The objects' bounds in voxels (max exclusive; empty without objects).
    glm::ivec3 objectsMin(0), objectsMax(0);
    if (in.scene.dynamic.present()) {
        objectsMin = in.scene.dynamic.origin;
        objectsMax = in.scene.dynamic.origin + in.scene.dynamic.grid.sizeInVoxels();
    }
    const bool changed = changes.newWorld || changes.staticWorldChanged || changes.lightsUploaded ||
                         changes.skyChanged;
    const std::uint32_t levels = std::clamp(lighting.vct.levels, 1u, shared::VCT_MAX_LEVELS);
    // The box the clipmap keeps over: the static world and the objects.
    const auto [worldMin, worldMax] =
        unionOf(glm::ivec3(0), in.scene.grid.sizeInVoxels(), objectsMin, objectsMax);
    shared::VctParams p{};
    for (std::uint32_t l = 0; l < shared::VCT_MAX_LEVELS; ++l) {
        p.levelOrigin[l] = glm::ivec4(levelOrigin(in.camera.position, l, worldMin, worldMax),
                                      int(shared::VCT_BASE_TEXEL << l));
        p.prevOrigin[l] = mPrevOrigins[l];
    }
    p.levels = levels;
    // Last frame's volume still holds this frame's light: nothing changed, the same settings.
    const bool previousValid = mPrepared && in.frameIndex == mLastFrame + 1 && !changed &&
                               mPrevSettings == lighting.vct && mPrevSeed == lighting.seed;
    p.flags = (lighting.vct.leakMitigation ? shared::VCT_LEAK_MITIGATION : 0u) |
              (lighting.vct.extraBounce ? shared::VCT_EXTRA_BOUNCE : 0u) |
              (previousValid ? shared::VCT_PREVIOUS_VALID : 0u) |
              (lighting.vct.extraBounce ? 0u : shared::VCT_IN_PLACE);
    p.seed = lighting.seed;
    p.startOffset = lighting.vct.startOffset;
    // The objects' bounds now and last frame: where they are and where they left.
    const auto [dynamicMin, dynamicMax] =
        unionOf(objectsMin, objectsMax, mPrevDynamicMin, mPrevDynamicMax);
    p.dynamicMin = glm::ivec4(dynamicMin, 0);
    p.dynamicMax = glm::ivec4(dynamicMax, 0);
    p.refreshPeriod = std::max(lighting.vct.refreshPeriod, 1u);
    p.frame = in.frameIndex;
    uploader.write(mParams, 0, &p, sizeof(p));

    // The blocks of texels vct.classify visits (vct_block_list.h). A texel re-injected in a world
    // that has not changed since its last injection gets the values it holds: the injection is a
    // function of the world, the objects, the lights, the sky, the settings and the texel's place
    // (its jitter is not the frame's). Every texel is due once in any refreshPeriod frames, so
    // that many frames after the objects last changed the rotation can change nothing, and only
    // the texels new to a level need visiting. The extra bounce's values change from frame to
    // frame (it reads last frame's volume), so it keeps the rotation, over the blocks that hold
    // content; its volume was written two frames ago, so the texels new since then are visited too.
    if (changes.newWorld || changes.staticWorldChanged) ++mGridVersion;
    const bool objectsChanged =
        changes.objectsMoved || objectsMin != mPrevDynamicMin || objectsMax != mPrevDynamicMax;
    if (!previousValid) {
        mObjectsChanging = false;  // every texel is injected now, with today's objects
    } else if (objectsChanged) {
        mObjectsChanging = true;
        mObjectsChangedFrame = in.frameIndex;
    }
    const bool rotationMatters =
        lighting.vct.extraBounce ||
        (mObjectsChanging && in.frameIndex - mObjectsChangedFrame < p.refreshPeriod);
    mBlockList.clear();
    if (lighting.vct.classifyAll || !previousValid ||
        (lighting.vct.extraBounce && !mPreviousWasValid)) {
        mBlockList.addAll(levels);
    } else {
        for (std::uint32_t l = 0; l < levels; ++l) {
            const glm::ivec4 now = p.levelOrigin[l];
            mBlockList.addNew(l, now, mPrevOrigins[l]);
            if (lighting.vct.extraBounce) mBlockList.addNew(l, now, mPrevPrevOrigins[l]);
            if (!rotationMatters) continue;
            mBlockList.addContent(l, now, in.scene.grid, mGridVersion);
            mBlockList.addBox(l, now, dynamicMin, dynamicMax);  // the objects' content is inside
            if (lighting.vct.extraBounce)
                mBlockList.addBox(l, now, mPrevPrevDynamicMin, mPrevPrevDynamicMax);
        }
    }
    const std::span<const std::uint32_t> blocks = mBlockList.blocks();
    mBlockCount = std::uint32_t(blocks.size());
    if (mBlockCount > 0) uploader.write(mBlocks, 0, blocks.data(), blocks.size_bytes());

    mPrevPrevOrigins = mPrevOrigins;
    for (std::uint32_t l = 0; l < shared::VCT_MAX_LEVELS; ++l) mPrevOrigins[l] = p.levelOrigin[l];
    mPrevPrevDynamicMin = mPrevDynamicMin;
    mPrevPrevDynamicMax = mPrevDynamicMax;
    mPrevDynamicMin = objectsMin;
    mPrevDynamicMax = objectsMax;
    mPreviousWasValid = previousValid;
    mPrepareMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    mPrevSettings = lighting.vct;
    mPrevSeed = lighting.seed;
    mLevels = levels;
    mExtraBounce = lighting.vct.extraBounce;
    mLastFrame = in.frameIndex;
    mPrepared = true;
}

void VoxelConeTracing::record(FrameCommands& commands, const FrameBuffers& frame) {
    gpu::CommandList& cmd = commands.current();
    // Without the extra bounce nothing reads last frame's volume while this one is written: one
    // volume, updated in place (VCT_IN_PLACE), so the texels that keep their values cost no copy.
    if (!mExtraBounce) mCurrent = 0;
    gpu::Buffer& volume = mVolumes[mCurrent];
    const gpu::Buffer& previous = mExtraBounce ? mVolumes[mCurrent ^ 1u] : volume;
    // No block listed: every texel already holds this frame's values.
    if (mBlockCount > 0) {
        cmd.fillBuffer(mList, 0);  // the injection list's count
        mInject.record(cmd, frame.scene,
                       {frame.frameParams, mParams, previous, volume, mList, mBlocks}, mBlockCount);
    }
    mCones.record(
        cmd, frame.scene,
        {frame.frameParams, mParams, frame.gbuffer, volume, frame.indirect, frame.radiance},
        frame.size);
    mCurrent ^= 1u;
}

void VoxelConeTracing::collect(FrameResult& result) {
    result.vctUsed = true;
    result.vctBlocks = mBlockCount;
    result.vctPrepareMs = mPrepareMs;
}

}  // namespace engine::render
