#include "render/dvf_sky/dvf_sky.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gpu/command_list.h"
#include "render/dvf_sky/dvf_directions.h"
#include "render/frame_commands.h"
#include "render/frame_result.h"

namespace engine::render {
namespace {

// All edits as one sphere around their union: conservative when a frame has more than fit.
glm::vec4 boundingSphere(const std::vector<glm::vec4>& spheres) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec4& s : spheres) {
        lo = glm::min(lo, glm::vec3(s) - s.w);
        hi = glm::max(hi, glm::vec3(s) + s.w);
    }
    return glm::vec4((lo + hi) * 0.5f, glm::length(hi - lo) * 0.5f);
}

template <class T>
std::vector<T> readBuffer(gpu::Context& ctx, const gpu::Buffer& src, std::uint64_t bytes) {
    gpu::Buffer host(ctx, gpu::BufferKind::Readback, bytes, "dvf.readback");
    gpu::CommandList cmd(ctx);
    cmd.begin();
    cmd.copyBuffer(src, host, {{0, 0, bytes}});
    cmd.barrier();
    cmd.submitAndWait();
    std::vector<T> out(bytes / sizeof(T));
    std::memcpy(out.data(), host.mapped(), bytes);
    return out;
}

}  // namespace

DvfSky::DvfSky(gpu::Context& ctx)
    : mCtx(ctx),
      mInvalidate(ctx, "dvf.invalidate", "dvf_sky/invalidate_masks"),
      mTakeBatch(ctx, "dvf.take_batch", "dvf_sky/take_batch"),
      mBuild(ctx, "dvf.build", "dvf_sky/build_masks"),
      mShade(ctx, "dvf.shade", "dvf_sky/shade_sky"),
      mReference(ctx, "sky.reference", "dvf_sky/sky_reference") {}

std::uint64_t DvfSky::deviceBytes(glm::uvec2 frameSize) {
    return std::uint64_t(shared::DVF_CAPACITY) * (sizeof(shared::DvfSlot) + sizeof(std::uint32_t)) +
           6 * shared::DVF_DIRECTIONS * sizeof(float) + sizeof(shared::DvfHeader) +
           sizeof(shared::DvfParams) + 2ull * frameSize.x * frameSize.y * sizeof(glm::vec4);
}

bool DvfSky::supports(glm::ivec3 cells) {
    return cells.x <= int(shared::DVF_MAX_CELLS_XZ) && cells.z <= int(shared::DVF_MAX_CELLS_XZ) &&
           cells.y <= int(shared::DVF_MAX_CELLS_Y);
}

TechniquePlan DvfSky::plan(const lighting::LightingSettings& l, const SceneShape& scene,
                           glm::uvec2 size) {
    TechniquePlan p;
    p.runs = lighting::usesSkyTerm(l) && supports(scene.sizeInVoxels / world::kBrickDim);
    p.deviceBytes = deviceBytes(size);
    return p;
}

std::string DvfSky::describe(const lighting::LightingSettings& l) {
    return l.sky == lighting::Sky::Dvf ? "sky dvf" : "sky reference";
}

void DvfSky::allocate() {
    using gpu::BufferKind;
    mParams = gpu::Buffer(mCtx, BufferKind::Storage, sizeof(shared::DvfParams), "dvf.params");
    mHeader = gpu::Buffer(mCtx, BufferKind::Storage, sizeof(shared::DvfHeader), "dvf.header");
    mHeaderHost =
        gpu::Buffer(mCtx, BufferKind::Readback, sizeof(shared::DvfHeader), "dvf.headerHost");
    mSlots =
        gpu::Buffer(mCtx, BufferKind::Storage,
                    std::uint64_t(shared::DVF_CAPACITY) * sizeof(shared::DvfSlot), "dvf.slots");
    mQueue = gpu::Buffer(mCtx, BufferKind::Storage,
                         std::uint64_t(shared::DVF_CAPACITY) * sizeof(std::uint32_t), "dvf.queue");
    mWeights = gpu::Buffer(mCtx, BufferKind::Storage, 6 * shared::DVF_DIRECTIONS * sizeof(float),
                           "dvf.weights");
    mStats.tableBytes = mSlots.size() + mQueue.size() + mWeights.size() + mHeader.size();
    mClear = true;
}

std::vector<glm::vec4> DvfSky::changedRegions(const FrameChanges& changes,
                                              const world::Scene& scene) {
    std::vector<glm::vec4> edits;
    for (const glm::ivec3& cell : changes.editedCells) {
        edits.push_back(glm::vec4(glm::vec3(cell * 8) + 4.0f, 4.0f * std::sqrt(3.0f)));
    }
    // The objects' old and new bounds, when they moved or vanished.
    if (changes.objectsMoved || (mPrevDynamicBounds && !scene.dynamic.present())) {
        if (mPrevDynamicBounds) edits.push_back(*mPrevDynamicBounds);
        mPrevDynamicBounds.reset();
        if (scene.dynamic.present()) {
            const glm::vec3 size(scene.dynamic.grid.sizeInVoxels());
            mPrevDynamicBounds =
                glm::vec4(glm::vec3(scene.dynamic.origin) + size * 0.5f, glm::length(size) * 0.5f);
            edits.push_back(*mPrevDynamicBounds);
        }
    }
    return edits;
}

void DvfSky::prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                     shared::FrameParams&) {
    if (mSlots.size() == 0) allocate();  // first use
    if (in.size != mSize) {
        mSize = in.size;
        // The term per pixel, then (the reference's) running sum per pixel.
        mSky = gpu::Buffer(mCtx, gpu::BufferKind::Storage,
                           2ull * mSize.x * mSize.y * sizeof(glm::vec4), "sky.term");
    }
    if (!mWeightsUploaded) {
        const auto weights = dvfSkyWeights();
        uploader.write(mWeights, 0, weights.data(), sizeof(weights));
        mWeightsUploaded = true;
    }
    const lighting::Sky mode = in.lighting.sky;
    const std::vector<glm::vec4> edits = changedRegions(changes, in.scene);
    // A new world, or a table three-quarters full (shade_sky.comp stops inserting there): start
    // again from an empty table, which the view refills within a few frames.
    // A frame without the term (edits then went unseen) or with the reference before it: the same.
    if (changes.newWorld || mStats.usedSlots >= shared::DVF_CAPACITY - shared::DVF_CAPACITY / 4u ||
        mMode != mode)
        mClear = true;
    const bool restart = changes.restartsAccumulation() || mMode != mode;
    mMode = mode;

    shared::DvfParams p{};
    p.budget = kMasksPerFrame;
    p.frame = in.frameIndex;
    p.seed = in.lighting.seed;
    p.flags = restart ? shared::DVF_FLAG_RESTART : 0u;
    p.samples = kReferenceRaysPerFrame;
    if (!mClear && !edits.empty()) {
        if (edits.size() <= shared::DVF_MAX_EDITS) {
            std::copy(edits.begin(), edits.end(), p.edits);
            p.editCount = static_cast<std::uint32_t>(edits.size());
        } else {
            p.edits[0] = boundingSphere(edits);
            p.editCount = 1;
        }
    }
    mEditCount = p.editCount;
    uploader.write(mParams, 0, &p, sizeof(p));
}

void DvfSky::record(FrameCommands& commands, const FrameBuffers& frame) {
    gpu::CommandList& cmd = commands.current();
    const SceneBindings& scene = frame.scene;
    const DvfSkyIo all{frame.frameParams, mParams,       mHeader,        mSlots, mQueue,
                       mWeights,          frame.gbuffer, frame.radiance, mSky};
    if (mMode == lighting::Sky::Reference) {
        mReference.record(cmd, scene, all, screenGroups(mSize));
        return;
    }
    if (mClear) {
        cmd.fillBuffer(mSlots, 0);  // every key DVF_EMPTY_KEY, every state 0
        cmd.fillBuffer(mHeader, 0);
        mClear = false;
        mStats.queued = 0;
        mStats.usedSlots = 0;
    }
    if (mEditCount) mInvalidate.record(cmd, scene, all, {shared::DVF_CAPACITY / 64u, 1});
    mTakeBatch.record(cmd, scene, all, {1, 1});
    // The batch is min(queue, budget); the queue is what the last frame left, unless this frame's
    // edits add to it — then the whole budget, whose surplus workgroups return at once.
    const std::uint32_t buildGroups =
        mEditCount ? kMasksPerFrame : std::min(kMasksPerFrame, mStats.queued);
    mBuild.record(cmd, scene, all, {buildGroups, 1});
    mShade.record(cmd, scene, all, screenGroups(mSize));
    cmd.copyBuffer(mHeader, mHeaderHost, {{0, 0, mHeader.size()}});  // read after the submission
}

void DvfSky::collect(FrameResult& result) {
    result.skyUsed = true;
    if (mMode == lighting::Sky::Dvf) {
        shared::DvfHeader h{};
        std::memcpy(&h, mHeaderHost.mapped(), sizeof(h));
        mStats.usedSlots = h.used;
        mStats.queued = h.tail - h.head;
        mStats.tracedMasks = h.batchCount;
        mStats.tracedRays = h.tracedRays;
    }
    result.sky = mStats;
}

std::vector<shared::DvfSlot> DvfSky::readSlots() {
    return readBuffer<shared::DvfSlot>(mCtx, mSlots, mSlots.size());
}

std::vector<glm::vec4> DvfSky::readSkyTerm() {
    return readBuffer<glm::vec4>(mCtx, mSky, std::uint64_t(mSize.x) * mSize.y * sizeof(glm::vec4));
}

}  // namespace engine::render
