// The voxel-face irradiance cache on the GPU (Cosin Ayerbe et al. §4; layouts in
// shaders/shared/irradiance_cache.h, host bookkeeping in irradiance_cache_directory.h, shaders in
// shaders/irradiance_cache/).
//
// Each frame, while the GPU runs the frame's first submission: the host reads the visible voxels
// off a G-buffer (the previous frame's; plus an N^3 neighbourhood around visible dynamic voxels),
// lets the directory pick this frame's updates within the ray budget, and queues the uploads
// ("cache.prepare"); then the stages run in the second submission, each a timed pass:
//   cache.faces         which faces have work: the passes below run one invocation per such face
//   cache.list_dispatch the workgroups of those passes (indirect dispatches), from the lists'
//   lengths cache.trace_static  new or invalidated static entries trace S of their K directions per
//   face
//                       (their phase's), until all K are cached
//   cache.visibility_static   static entries re-trace only the dynamic grid (divide and win)
//   cache.visibility_dynamic  dynamic entries trace the dynamic grid, and the static world on the
//                       first update of each phase (its hits are cached like the static entries')
//   cache.bounce        light leaving each ray's hit -> E_new, blended into the entry
//   cache.filter        3^3 filter over neighbouring entries of the same set
//   cache.gather        per pixel: albedo/pi * E from the pixel's set at its level, added to the
//                       radiance; lists the pixels that find no value there
//   cache.gather_late   those pixels only (an indirect dispatch): the other level, the fallback
// GPU storage grows with the entries (doubling) up to the budget; it never depends on the world's
// size.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/uploader.h"
#include "lighting/irradiance_cache_settings.h"
#include "render/irradiance_cache/irradiance_cache_directory.h"
#include "render/passes/lit_pass.h"
#include "render/technique.h"
#include "shared/gbuffer.h"
#include "world/brick_grid.h"

namespace engine::gpu {
class CommandList;
class Uploader;
}  // namespace engine::gpu

namespace engine::render {

struct IrradianceCacheStats {
    std::uint32_t visibleStatic =
        0;  // distinct static keys seen by the camera (voxels; with LOD, also 2x2 patches)
    std::uint32_t visibleDynamic = 0;  // distinct dynamic voxels seen by the camera
    std::uint32_t updated = 0;         // entries updated this frame (with the neighbourhoods)
    std::uint32_t dynamicEntries = 0;  // of them, dynamic-set entries
    std::uint32_t traced = 0;          // static entries that traced static rays this frame
    std::uint32_t waiting = 0;         // visible entries the ray budget left for later frames
    std::uint32_t entries = 0;         // live entries
    std::uint32_t coarseEntries =
        0;  // of them, coarse ones seen this frame (one face of a 2x2 patch, cache_lod.h)
    std::uint32_t dropped = 0, evicted = 0, invalidated = 0;
    std::uint64_t rays = 0;  // rays this frame's updates may trace (what the budget counts)
    std::uint64_t raysTraced =
        0;                    // rays the GPU traced (counted by the shaders; excluding shadow rays)
    std::uint64_t bytes = 0;  // GPU memory the cache holds
};

// What the host's update pick needs of the frame.
struct CacheFrameInput {
    std::span<const shared::GBufferTexel> gbuffer;  // whose visible voxels are kept up to date
    const world::BrickGrid* grid =
        nullptr;         // the static world, for the coarse entries' rule (cache_lod.h)
    glm::uvec2 size{0};  // this frame's image
    double timeSeconds = 0.0;
    std::uint32_t frameIndex = 0;
    std::uint32_t seed = 0;                  // the lighting seed
    std::vector<glm::ivec3> editedCellMins;  // static 8^3 cells edited since the last frame
    bool lightsChanged = false;              // an emitter or the sun changed: every entry restarts
    // The dynamic grid was uploaded (an object moved or appeared): dynamic entries and the static
    // ones near objects are updated every frame only then.
    bool objectsMoved = true;
};

// Runs with `--indirect cache` beside any method but the reference (lighting::usesCache).
class IrradianceCache : public Technique {
public:
    explicit IrradianceCache(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    // Keeps what the update pick needs; a new world empties the cache.
    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    // The frame goes to the GPU in two submissions: the host picks the cache's updates from the
    // last frame's visible voxels while the GPU runs the first (primary rays, direct light), and
    // the second (the cache's passes, tonemapping) follows. Without last frame's voxels (the
    // cache's first frame, a new size) the first submission waits and this frame's are read.
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    // Reads the rays the shaders counted into stats().
    void collect(FrameResult& result) override;
    // A frame without the cache: the next one has no visible voxels of the last frame.
    void skip() override { mGBufferHostValid = false; }

    void clear();

    const IrradianceCacheStats& stats() const { return mStats; }
    const IrradianceCacheDirectory& directory() const { return mDirectory; }
    // For tests: this frame's update list and the selected hit of each traced ray.
    std::span<const std::uint32_t> updateList() const { return mUpdate; }
    const gpu::Buffer& selectedHits() const { return mSelectedHits; }
    const gpu::Buffer& filtered() const { return mFiltered; }
    std::uint32_t raysPerUpdate() const { return mSettings.raysPerUpdate; }
    // The direction index ray j of `slot`'s update this frame used (its phase's).
    std::uint32_t directionIndex(std::uint32_t slot, std::uint32_t j) const;
    // All CACHE_DIRECTION_SETS direction sets, K each, in the face frame.
    std::span<const glm::vec4> directions() const { return mDirections; }
    // The host's copy of the shaders' per-entry directions (irradiance_cache.glsl), bit for bit:
    // which set and mirror entry (voxel, set) uses under a lighting seed, and its direction k on
    // `face` in world space under the current seed.
    static std::uint32_t directionRotation(glm::ivec3 voxel, std::uint32_t set, std::uint32_t seed,
                                           std::uint32_t coarse = 0);
    glm::vec3 rayDirection(glm::ivec3 voxel, std::uint32_t set, std::uint32_t face, std::uint32_t k,
                           std::uint32_t coarse = 0) const;
    static std::uint64_t bytesPerSlot(const lighting::IrradianceCacheSettings& settings);

private:
    struct Io {
        const gpu::Buffer& frameParams;
        const gpu::Buffer& gbuffer;
        gpu::Buffer& radiance;  // read and written: the indirect term is added
        gpu::Buffer& indirect;  // written: the indirect term alone
    };
    // The host's work: picks this frame's updates from the visible voxels within the ray budget
    // and queues the uploads.
    void pickUpdates(const lighting::IrradianceCacheSettings& settings,
                     const CacheFrameInput& frame, gpu::Uploader& uploader, gpu::CommandList& cmd);
    void recordPasses(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io);
    void reset(const lighting::IrradianceCacheSettings& settings, std::uint32_t seed);
    void ensureCapacity(std::uint32_t slots, gpu::CommandList& cmd);

    gpu::Context& mCtx;
    LitPass mFaces, mListDispatch, mTraceStatic, mVisibilityStatic, mVisibilityStaticFull,
        mVisibilityDynamic, mVisibilityDynamicFull, mBounce, mFilter, mGather, mGatherLate;
    lighting::IrradianceCacheSettings mSettings;
    bool mConfigured = false;
    bool mDirectionsUploaded = false;
    std::uint32_t mSeed = 0;  // the lighting seed the cached hits were traced with
    IrradianceCacheDirectory mDirectory{1};
    std::vector<glm::vec4> mDirections;
    std::vector<std::uint32_t> mUpdate, mTrace;  // mUpdate: static entries first
    std::uint32_t mStaticUpdates = 0;
    std::uint32_t mCapacity = 0;  // slots the GPU buffers hold
    std::uint32_t mFrameIndex = 0;
    glm::uvec2 mImage{0};
    IrradianceCacheStats mStats;
    gpu::Buffer mParams, mDirectionBuffer, mEntries, mTable, mLists, mStaticHits, mSelectedHits,
        mIrradiance, mFiltered;
    gpu::Buffer mCounters, mCountersHost;
    gpu::Buffer mLatePixels;  // cache.gather's list for cache.gather_late, one uint per pixel
    std::vector<gpu::Buffer>
        mRetired;  // replaced buffers, kept until the frame that copied them is done
    // This frame's input, kept from prepare() for the pick in record().
    lighting::IrradianceCacheSettings mFrameSettings;
    CacheFrameInput mFrameInput;
    // The cache's uploads, recorded while the frame's first submission may still read the
    // frame's uploader's staging memory.
    gpu::Uploader mUploader;
    // The last frame's G-buffer on the host: the visible voxels for the next frame's pick.
    gpu::Buffer mGBufferHost;
    bool mGBufferHostValid = false;
    bool mSplitFrame = false;  // this frame's first submission waited for its G-buffer
    double mPickMs = 0.0;      // CPU time of this frame's pick and uploads
};

}  // namespace engine::render
