// DvfSky: sky light for the real-time methods from discrete visibility fields (Günay & Akyüz,
// "Real-time Discrete Visibility Fields for Ray-Traced Dynamic Scenes"), and its brute-force
// reference (`--sky dvf|reference`). Owns the GPU hash table of masks — one slot per (8³ cell,
// face orientation) that a pixel has looked at, 64 hemi-octahedral sky directions each — the trace
// queue, the per-face direction weights and the per-pixel sky term.
//
// Memory follows the view: a slot is taken when a pixel's face first needs it (dvf.shade), and its
// mask is traced in a later frame's dvf.build, at most `kMasksPerFrame` masks per frame. An edit
// (and a moving object's old and new bounds) marks, in every slot, only the directions that can
// pass through the changed region (dvf.invalidate); those alone are traced again. The table has a
// fixed size (DVF_CAPACITY slots, 3 MiB, allocated on first use); when it is three-quarters full
// the host clears it and the view refills it. All in the frame's one submission; the header (slots
// used, queue, rays traced) is copied to the host after the frame for the statistics.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/uploader.h"
#include "lighting/lighting_settings.h"
#include "render/dvf_sky/dvf_sky_passes.h"
#include "render/technique.h"

namespace engine::render {

struct DvfSkyStats {
    std::uint32_t usedSlots = 0;    // (cell, face) masks held
    std::uint32_t queued = 0;       // masks waiting to be traced after this frame
    std::uint32_t tracedMasks = 0;  // masks traced this frame
    std::uint32_t tracedRays = 0;   // rays traced for them (dirty directions x rays per direction)
    std::uint64_t tableBytes = 0;   // device bytes of the table, queue and weights (fixed)
};

// Runs with a sky term (lighting::usesSkyTerm) on a world its keys cover (supports()).
class DvfSky : public Technique {
public:
    static constexpr std::uint32_t kMasksPerFrame = 1024;  // build workgroups per frame
    static constexpr std::uint32_t kReferenceRaysPerFrame = 16;

    explicit DvfSky(gpu::Context& ctx);
    static TechniquePlan plan(const lighting::LightingSettings& l, const SceneShape& scene,
                              glm::uvec2 size);
    static std::string describe(const lighting::LightingSettings& l);

    // Before the frame's uploads are recorded: the regions whose voxels changed (the edited
    // cells, the objects' old and new bounds) mark the masks' directions through them stale.
    void prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                 shared::FrameParams& params) override;
    // After the direct lighting: the term is added to the radiance.
    void record(FrameCommands& commands, const FrameBuffers& frame) override;
    // Reads the copied header.
    void collect(FrameResult& result) override;
    // A frame without the sky term: its edits are not seen, so the next frame with it starts
    // afresh.
    void skip() override { mMode = lighting::Sky::None; }

    const DvfSkyStats& stats() const { return mStats; }
    // Test hooks: the table and the last frame's sky term per pixel, read back.
    std::vector<shared::DvfSlot> readSlots();
    std::vector<glm::vec4> readSkyTerm();
    // Device bytes at `frameSize`: the table (allocated on first use) and the per-pixel term.
    static std::uint64_t deviceBytes(glm::uvec2 frameSize);
    // Worlds the key packing covers (shared/dvf_sky.h).
    static bool supports(glm::ivec3 sizeInCells);

private:
    void allocate();
    // Bounding spheres (xyz centre, w radius) of the regions whose voxels changed.
    std::vector<glm::vec4> changedRegions(const FrameChanges& changes, const world::Scene& scene);

    gpu::Context& mCtx;
    DvfSkyPass mInvalidate, mTakeBatch, mBuild, mShade, mReference;
    gpu::Buffer mParams, mHeader, mHeaderHost, mSlots, mQueue, mWeights, mSky;
    glm::uvec2 mSize{0};
    lighting::Sky mMode = lighting::Sky::None;
    bool mClear = true;  // the table must be emptied before the next frame's passes
    bool mWeightsUploaded = false;
    std::uint32_t mEditCount = 0;
    std::optional<glm::vec4> mPrevDynamicBounds;  // the objects' last bounding sphere
    DvfSkyStats mStats;
};

}  // namespace engine::render
