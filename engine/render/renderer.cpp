#include "render/renderer.h"

#include <chrono>
#include <cmath>
#include <cstring>

#include "core/memory_budget.h"
#include "gpu/command_list.h"
#include "gpu/presenter.h"
#include "render/baselines/light_sampling_params.h"
#include "render/memory_plan.h"
#include "render/reference/reference_params.h"
#include "render/restir/restir_params.h"
#include "render/shader_features.h"

namespace engine::render {

namespace {

bool sameView(const world::CameraPreset& a, const world::CameraPreset& b) {
    return a.position == b.position && a.target == b.target && a.fovYDegrees == b.fovYDegrees;
}

bool sameSky(const world::SkyLight& a, const world::SkyLight& b) {
    return a.sunDirection == b.sunDirection && a.sunRadiance == b.sunRadiance && a.skyRadiance == b.skyRadiance;
}

}  // namespace

double FrameResult::totalMs() const {
    double total = 0.0;
    for (const auto& [name, ms] : passMs) total += ms;
    return total;
}

double FrameResult::passMsOf(const std::string& name) const {
    for (const auto& [n, ms] : passMs) {
        if (n == name) return ms;
    }
    return 0.0;
}

Renderer::Renderer(gpu::Context& ctx)
    : mCtx(ctx),
      mWorld(ctx),
      mGpuEmitters(ctx),
      mUploader(ctx),
      mCacheUploader(ctx),
      mTimer(ctx, 24),
      mPresentTimer(ctx, 1),
      mLateTimer(ctx, 16),
      mPrimary(ctx),
      mPreview(ctx),
      mRestirInitial(ctx),
      mRestirTemporal(ctx),
      mRestirSpatial(ctx),
      mRestirShade(ctx),
      mLightSampling(ctx),
      mReference(ctx),
      mTonemap(ctx),
      mCache(ctx),
      mLightTiles(ctx),
      mRegir(ctx),
      mPathIndirect(ctx),
      mDvfSky(ctx),
      mVct(ctx) {
    mFrameParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::FrameParams), "frame.params");
    mRestirParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::RestirParams), "restir.params");
    mLightSamplingParams =
        gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::LightSamplingParams), "baselines.params");
    mReferenceParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::ReferenceParams), "reference.params");
}

std::uint64_t Renderer::frameBytesPerPixel() {
    // The buffers resize() makes, per pixel; keep the two in step.
    return 3 * sizeof(shared::GBufferTexel) + 4 * sizeof(shared::Reservoir) + 3 * sizeof(glm::vec4) +
           sizeof(std::uint32_t) + sizeof(glm::uvec4);
}

void Renderer::resize(std::uint32_t width, std::uint32_t height) {
    if (mSize == glm::uvec2(width, height)) return;
    mSize = {width, height};
    std::uint64_t pixels = std::uint64_t(width) * height;
    for (int i = 0; i < 2; ++i) {
        mGBuffers[i] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(shared::GBufferTexel),
                                   i ? "frame.gbuffer1" : "frame.gbuffer0");
        mFinalReservoirs[i] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(shared::Reservoir),
                                          i ? "restir.reservoirs1" : "restir.reservoirs0");
    }
    mCandidates = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(shared::Reservoir), "restir.candidates");
    mOwnReservoirs = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(shared::Reservoir), "restir.own");
    // Passes that only read these fetch them as uvec4 texels (loadGBuffer, loadReservoir): one gather
    // per 16 B on lavapipe, where a storage-buffer read at a lane-varying index loops over the lanes.
    for (gpu::Buffer* b : {&mGBuffers[0], &mGBuffers[1], &mFinalReservoirs[0], &mFinalReservoirs[1], &mCandidates, &mOwnReservoirs}) {
        b->setTexelFormat(VK_FORMAT_R32G32B32A32_UINT);
    }
    mAccumulation = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::vec4), "reference.accumulation");
    mRadiance = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::vec4), "frame.radiance");
    mLdr = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(std::uint32_t), "frame.ldr");
    mRayStats = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::uvec4), "frame.rayStats");
    mIndirect = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::vec4), "frame.indirect");
    mGBufferHost = gpu::Buffer(mCtx, gpu::BufferKind::Readback, pixels * sizeof(shared::GBufferTexel), "frame.gbufferHost");
    mGBufferHostValid = false;
    resetHistory();
}

void Renderer::resetHistory() {
    mHistoryValid = false;
    mAccumulatedSamples = 0;
    mPrevCamera.reset();
    mPrevTime.reset();
}

FrameResult Renderer::render(world::Scene& scene, const world::CameraPreset& camera, const FrameSettings& settings,
                             const lighting::LightingSettings& lighting, gpu::Presenter* presenter) {
    if (mSize != glm::uvec2(settings.width, settings.height) || mWorld.needsFullUpload(scene.grid)) {
        // About to allocate the frame's buffers or the world's GPU copy: refuse, with the plan,
        // what would not fit, before allocating any of it.
        const MemoryPlan plan = planMemory(scene, {settings.width, settings.height}, lighting);
        if (Status s = checkMemoryPlan(plan, memoryBudgetBytes(), "world '" + scene.name + "'"); !s)
            throw MemoryBudgetExceeded(s.error().message);
    }
    resize(settings.width, settings.height);
    if (mPrevLighting && !(*mPrevLighting == lighting)) {
        mHistoryValid = false;
        mAccumulatedSamples = 0;
    }
    FrameResult result;

    // CPU side first: the emitter list reads the grid's touched cells before they are cleared.
    auto start = std::chrono::steady_clock::now();
    mEmitters.setSettings({lighting.brickLights});
    result.emitterUpdate = mEmitters.update(scene);
    result.emitterUpdateMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    result.emitters = mEmitters.aliveCount();
    // A light added, removed or changed: last frame's reservoirs were resampled from the old set
    // of lights, so their weights are wrong for the new one — too bright for the lights that
    // remain after a removal, blind to a new light for as long as their M outweighs the fresh
    // candidates. One frame without temporal reuse starts the history from the current lights.
    const lighting::EmitterUpdateStats& lightEdit = result.emitterUpdate;
    if (!lightEdit.full && (lightEdit.added || lightEdit.removed || lightEdit.changed)) mHistoryValid = false;
    // Objects at this frame's time; their previous pose is at the last frame's (this one's on a
    // first frame, like the camera), so motion vectors follow them.
    start = std::chrono::steady_clock::now();
    world::updateDynamicObjects(scene.objects, scene.dynamic, settings.timeSeconds, mPrevTime.value_or(settings.timeSeconds));
    result.dynamicUpdateMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    // Every pass compiled without the code of the features this frame does not use.
    const ShaderFeatures features = shaderFeatures(lighting, scene.dynamic.present());
    const std::span<const std::uint32_t> specialization = mSpecializeShaders ? std::span(features) : std::span<const std::uint32_t>();
    gpu::CommandList cmd(mCtx, &mTimer);
    cmd.setSpecialization(specialization);
    cmd.begin();
    cmd.beginPass("upload");
    result.upload = mWorld.sync(scene, mUploader);
    const bool useCache = lighting.indirect == lighting::Indirect::Cache && lighting.method != lighting::Method::Reference;
    const bool usePath = lighting.indirect == lighting::Indirect::Path && lighting.method != lighting::Method::Reference;
    const bool useVct = lighting.indirect == lighting::Indirect::Vct && lighting.method != lighting::Method::Reference;
    std::vector<glm::ivec3> editedCells;  // for the cache: static rays through them are stale
    if (useCache && !result.upload.full) {
        const glm::ivec3 cells = scene.grid.sizeInCells();
        for (std::uint32_t c : scene.grid.touchedCells()) {
            editedCells.push_back(glm::ivec3(c % cells.x, (c / cells.x) % cells.y, c / (cells.x * cells.y)) * 8);
        }
    } else if (useCache) {
        mCache.clear();  // a new world
    }
    const bool useSky = lighting.skyTermUsed() && DvfSky::supports(scene.grid.sizeInCells());
    if (!useSky) mDvfSky.suspend();
    DvfSky::FrameInput skyInput;
    if (useSky) {
        // Regions whose voxels changed: the touched cells, and the objects' old and new bounds.
        skyInput.newWorld = result.upload.full;
        const glm::ivec3 cells = scene.grid.sizeInCells();
        for (std::uint32_t c : scene.grid.touchedCells()) {
            const glm::ivec3 cell(c % cells.x, (c / cells.x) % cells.y, c / (cells.x * cells.y));
            skyInput.edits.push_back(glm::vec4(glm::vec3(cell * 8) + 4.0f, 4.0f * std::sqrt(3.0f)));
        }
        if (result.upload.dynamicBytes || (mPrevDynamicBounds && !scene.dynamic.present())) {
            if (mPrevDynamicBounds) skyInput.edits.push_back(*mPrevDynamicBounds);
            mPrevDynamicBounds.reset();
            if (scene.dynamic.present()) {
                const glm::vec3 size(scene.dynamic.grid.sizeInVoxels());
                mPrevDynamicBounds = glm::vec4(glm::vec3(scene.dynamic.origin) + size * 0.5f, glm::length(size) * 0.5f);
                skyInput.edits.push_back(*mPrevDynamicBounds);
            }
        }
    }
    scene.grid.clearDirty();
    EmitterUploadStats lightUpload = mGpuEmitters.sync(mEmitters, mUploader);
    const bool worldChanged = result.upload.bricks || result.upload.cells || result.upload.dynamicBytes ||
                              lightUpload.slots || lightUpload.aliveAndAlias;

    shared::FrameParams params = makeFrameParams(camera, scene.sky, settings);
    shared::FrameParams prev = makeFrameParams(mPrevCamera.value_or(camera), scene.sky, settings);
    params.prevCameraPosition = prev.cameraPosition;
    params.prevCameraForward = prev.cameraForward;
    params.prevCameraRight = prev.cameraRight;
    params.prevCameraUp = prev.cameraUp;
    if (lightTilesUsed(lighting)) {
        params.lightTiles = mLightTiles.frameField();
        mLightTiles.writeParams(mUploader, mFrameIndex, lighting.seed);
    }
    if (regirUsed(lighting)) {
        mRegir.prepare(mUploader, scene.grid.sizeInVoxels(), lighting.regir, mFrameIndex, lighting.seed);
        params.regirGrid = mRegir.frameField();
    }
    mUploader.write(mFrameParams, 0, &params, sizeof(params));
    writeMethodParams(lighting);

    // The cache picks this frame's updates from the last frame's visible voxels, so its host work
    // (cache.prepare) needs nothing of this frame: the frame goes to the GPU in two submissions,
    // the host picks the cache's updates while lavapipe runs the first (primary rays and direct
    // light), and the second (the cache's passes, tonemapping) follows without a wait between.
    // Without last frame's voxels (the cache's first frame, a new size) the frame is split: up to
    // the G-buffer, read back, wait, then the rest.
    const bool splitFrame = useCache && !(mGBufferHostValid && mCache.configured());
    CacheFrameInput cacheInput;
    if (useCache) {
        cacheInput.size = mSize;
        cacheInput.timeSeconds = settings.timeSeconds;
        cacheInput.frameIndex = mFrameIndex;
        cacheInput.seed = lighting.seed;
        cacheInput.grid = &scene.grid;
        cacheInput.editedCellMins = editedCells;
        cacheInput.objectsMoved = result.upload.dynamicBytes > 0;
        cacheInput.lightsChanged = (!lightEdit.full && (lightEdit.added || lightEdit.removed || lightEdit.changed)) ||
                                   (mPrevSky && !sameSky(*mPrevSky, scene.sky));
    }
    auto prepareCache = [&](gpu::CommandList& list) {
        start = std::chrono::steady_clock::now();
        cacheInput.gbuffer = mGBufferHost.view<shared::GBufferTexel>();
        mCache.prepare(lighting.cache, cacheInput, mCacheUploader, list);
        result.cachePrepareMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    // What the accumulating estimators restart on (besides new settings, which drop the history).
    const bool viewOrWorldChanged = worldChanged || !mPrevCamera || !sameView(*mPrevCamera, camera);
    if (usePath) mPathIndirect.prepare(lighting, mSize, mFrameIndex, !mHistoryValid || viewOrWorldChanged, mUploader);
    if (useSky) {
        skyInput.mode = lighting.sky;
        skyInput.size = mSize;
        skyInput.frameIndex = mFrameIndex;
        skyInput.seed = lighting.seed;
        skyInput.viewOrWorldChanged = !mHistoryValid || viewOrWorldChanged;
        mDvfSky.prepare(skyInput, mUploader);
    }
    if (useVct) {
        VoxelConeTracing::Frame vctFrame;
        vctFrame.cameraPosition = camera.position;
        vctFrame.frameIndex = mFrameIndex;
        vctFrame.changed = result.upload.full || result.upload.bricks || result.upload.cells || lightUpload.slots ||
                           lightUpload.aliveAndAlias || (mPrevSky && !sameSky(*mPrevSky, scene.sky));
        if (scene.dynamic.present()) {
            vctFrame.dynamicMin = scene.dynamic.origin;
            vctFrame.dynamicMax = scene.dynamic.origin + scene.dynamic.grid.sizeInVoxels();
        }
        mVct.prepare(lighting, vctFrame, mUploader);
    }
    mUploader.record(cmd);
    if (lighting.method == lighting::Method::Reference && (mAccumulatedSamples == 0 || viewOrWorldChanged)) {
        cmd.fillBuffer(mAccumulation, 0);
        cmd.barrier();
        mAccumulatedSamples = 0;
    }
    if (!useCache && !usePath && !useVct) cmd.fillBuffer(mIndirect, 0);
    cmd.endPass();

    mPrimary.record(cmd, {mWorld, mFrameParams, mGBuffers[mCurrent]}, mSize);
    gpu::CommandList late(mCtx, &mLateTimer);
    late.setSpecialization(specialization);
    auto beginLate = [&] {
        late.begin();
        late.barrier();  // the first submission's writes (G-buffer, radiance, light tiles) before what reads them
        late.beginPass("cache.prepare");
        prepareCache(late);
        mCacheUploader.record(late);
        late.endPass();
    };
    gpu::CommandList* rest = &cmd;
    if (splitFrame) {
        cmd.copyBuffer(mGBuffers[mCurrent], mGBufferHost, {{0, 0, mGBuffers[mCurrent].size()}});
        cmd.barrier();
        cmd.submitAndWait();
        beginLate();
        rest = &late;
    }
    recordLighting(*rest, lighting, mHistoryValid);
    if (useSky) mDvfSky.record(*rest, {mWorld, mGpuEmitters}, {mFrameParams, mGBuffers[mCurrent], mRadiance});
    if (usePath)
        mPathIndirect.record(*rest, {mWorld, mGpuEmitters}, {mFrameParams, mGBuffers[mCurrent], mRadiance, mIndirect});
    if (useVct) mVct.record(*rest, {mWorld, mGpuEmitters}, {mFrameParams, mGBuffers[mCurrent], mRadiance, mIndirect}, mSize);
    const bool overlapped = useCache && !splitFrame;
    if (overlapped) {
        cmd.submit();
        beginLate();  // the host's cache work, while lavapipe runs the submission above
        rest = &late;
    }
    if (useCache) {
        mCache.record(*rest, {mWorld, mGpuEmitters}, {mFrameParams, mGBuffers[mCurrent], mRadiance, mIndirect});
        // This frame's visible voxels, for the next frame's cache updates.
        rest->copyBuffer(mGBuffers[mCurrent], mGBufferHost, {{0, 0, mGBuffers[mCurrent].size()}});
        rest->barrier();
    }
    mTonemap.record(*rest, {mFrameParams, mRadiance, mLdr}, mSize);
    rest->submitAndWait();
    if (overlapped) cmd.wait();  // done already: the queue runs submissions in order
    result.passMs = mTimer.results();
    if (useCache) {
        for (const auto& pass : mLateTimer.results()) result.passMs.push_back(pass);
    }
    if (useCache) {
        mCache.collect();
        mGBufferHostValid = true;
        result.cacheUsed = true;
        result.cacheSplitFrame = splitFrame;
        result.cache = mCache.stats();
    } else {
        mGBufferHostValid = false;
    }
    mPrevSky = scene.sky;
    if (useSky) {
        mDvfSky.collect();
        result.skyUsed = true;
        result.sky = mDvfSky.stats();
    }

    if (lighting.method == lighting::Method::Reference) mAccumulatedSamples += std::max(lighting.samplesPerFrame, 1u);
    result.referenceSamples = mAccumulatedSamples;
    mPrevCamera = camera;
    mPrevTime = settings.timeSeconds;
    mPrevLighting = lighting;
    mHistoryValid = true;
    mCurrent ^= 1u;
    ++mFrameIndex;
    if (presenter) {
        // A submission of its own, so only this pass waits for the swapchain image. The tonemap
        // pass's barrier orders the LDR writes before the copy in submission order.
        gpu::CommandList present(mCtx, &mPresentTimer);
        present.begin();
        presenter->record(present, mLdr, mSize);
        present.submitAndWait(presenter->submitSync());
        presenter->endFrame();
        for (const auto& pass : mPresentTimer.results()) result.passMs.push_back(pass);
    }
    return result;
}

void Renderer::writeMethodParams(const lighting::LightingSettings& lighting) {
    using lighting::Method;
    switch (lighting.method) {
        case Method::Preview:
            break;
        case Method::Restir:
        case Method::Ris: {
            const shared::RestirParams p = restirParams(lighting, mFrameIndex);
            mUploader.write(mRestirParams, 0, &p, sizeof(p));
            break;
        }
        case Method::Uniform:
        case Method::BruteForce: {
            const shared::LightSamplingParams p = lightSamplingParams(lighting, mFrameIndex);
            mUploader.write(mLightSamplingParams, 0, &p, sizeof(p));
            break;
        }
        case Method::Reference: {
            const shared::ReferenceParams p = referenceParams(lighting);
            mUploader.write(mReferenceParams, 0, &p, sizeof(p));
            break;
        }
    }
}

void Renderer::recordLighting(gpu::CommandList& cmd, const lighting::LightingSettings& lighting, bool historyValid) {
    using lighting::Method;
    const SceneBindings scene{mWorld, mGpuEmitters};
    gpu::Buffer& gbuffer = mGBuffers[mCurrent];
    if (lightTilesUsed(lighting)) mLightTiles.record(cmd, scene);  // before ReSTIR and the cache read them
    if (regirUsed(lighting)) mRegir.record(cmd, scene, mFrameParams, gbuffer, mSize);  // before the candidates
    switch (lighting.method) {
        case Method::Preview:
            mPreview.record(cmd, {mWorld, mFrameParams, gbuffer, mRadiance, mRayStats}, mSize);
            break;
        case Method::Restir:
        case Method::Ris: {
            gpu::Buffer& final = mFinalReservoirs[mCurrent];
            mRestirInitial.record(cmd, scene, {mFrameParams, mRestirParams, gbuffer, mCandidates}, mSize);
            gpu::Buffer* own = &mCandidates;
            if (lighting.method == Method::Restir && lighting.restir.temporal && historyValid) {
                mRestirTemporal.record(cmd, scene,
                                       {mFrameParams, mRestirParams, gbuffer, mGBuffers[mCurrent ^ 1u], mCandidates,
                                        mFinalReservoirs[mCurrent ^ 1u], mOwnReservoirs},
                                       mSize);
                own = &mOwnReservoirs;
            }
            if (lighting.method == Method::Restir && lighting.restir.spatial) {
                mRestirSpatial.record(cmd, scene, {mFrameParams, mRestirParams, gbuffer, *own, mCandidates, final}, mSize);
            } else {
                cmd.copyBuffer(*own, final, {{0, 0, own->size()}});
                cmd.barrier();
            }
            mRestirShade.record(cmd, scene, {mFrameParams, mRestirParams, gbuffer, final, mRadiance}, mSize);
            break;
        }
        case Method::Uniform:
        case Method::BruteForce:
            mLightSampling.record(cmd, scene, {mFrameParams, mLightSamplingParams, gbuffer, mRadiance}, mSize);
            break;
        case Method::Reference:
            mReference.record(cmd, scene, {mFrameParams, mReferenceParams, mAccumulation, mRadiance}, mSize);
            break;
    }
}

FrameImages Renderer::readback() {
    FrameImages images;
    images.width = mSize.x;
    images.height = mSize.y;
    const gpu::Buffer& gbuffer = mGBuffers[mCurrent ^ 1u];  // the last rendered frame's
    const gpu::Buffer* sources[] = {&mRadiance, &mLdr, &gbuffer, &mRayStats, &mIndirect};
    std::uint64_t total = 0;
    for (const gpu::Buffer* b : sources) total += b->size();
    gpu::Buffer readback(mCtx, gpu::BufferKind::Readback, total, "frame.readback");
    gpu::CommandList cmd(mCtx);
    cmd.begin();
    std::uint64_t offset = 0;
    for (const gpu::Buffer* b : sources) {
        cmd.copyBuffer(*b, readback, {{0, offset, b->size()}});
        offset += b->size();
    }
    cmd.barrier();
    cmd.submitAndWait();

    const auto* bytes = static_cast<const std::uint8_t*>(readback.mapped());
    auto take = [&](auto& vec, const gpu::Buffer& b, std::uint64_t& at) {
        vec.resize(b.size() / sizeof(vec[0]));
        std::memcpy(vec.data(), bytes + at, b.size());
        at += b.size();
    };
    std::uint64_t at = 0;
    take(images.radiance, mRadiance, at);
    take(images.rgba8, mLdr, at);
    take(images.gbuffer, gbuffer, at);
    take(images.rayStats, mRayStats, at);
    take(images.indirect, mIndirect, at);
    return images;
}

}  // namespace engine::render
