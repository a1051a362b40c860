#include "render/renderer.h"

#include <chrono>
#include <cstring>

#include "core/check.h"
#include "core/memory_budget.h"
#include "gpu/command_list.h"
#include "gpu/presenter.h"
#include "render/dvf_sky/dvf_sky.h"
#include "render/frame_commands.h"
#include "render/frame_plan.h"
#include "render/irradiance_cache/irradiance_cache.h"
#include "render/light_tiles/light_tiles.h"
#include "render/memory_plan.h"
#include "render/regir/regir_grid.h"
#include "render/upsampling/temporal_upsampling.h"
#include "shared/exposure.h"

namespace engine::render {

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
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
      mTimer(ctx, 24),
      mPresentTimer(ctx, 1),
      mLateTimer(ctx, 24),
      mPrimary(ctx),
      mTonemap(ctx) {
    for (const TechniqueEntry& t : techniqueRegistry()) mTechniques.push_back(t.make(ctx));
    mFrameParams =
        gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::FrameParams), "frame.params");
    mExposure =
        gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::ExposureState), "frame.exposure");
}

Renderer::~Renderer() = default;

template <class T>
T& Renderer::technique(std::string_view name) const {
    const std::span<const TechniqueEntry> registry = techniqueRegistry();
    for (std::size_t i = 0; i < registry.size(); ++i) {
        if (registry[i].name == name) return dynamic_cast<T&>(*mTechniques[i]);
    }
    CHECK_MSG(false, "no technique '%.*s'", int(name.size()), name.data());
    std::abort();
}

const IrradianceCache& Renderer::irradianceCache() const {
    return technique<IrradianceCache>("cache");
}
const LightTiles& Renderer::lightTiles() const { return technique<LightTiles>("light_tiles"); }
const RegirGrid& Renderer::regirGrid() const { return technique<RegirGrid>("regir"); }
const TemporalUpsampling& Renderer::temporalUpsampling() const {
    return technique<TemporalUpsampling>("upsampling");
}
DvfSky& Renderer::dvfSky() { return technique<DvfSky>("sky"); }

std::uint64_t Renderer::frameBytesPerPixel() {
    // The buffers resize() makes, per pixel; keep the two in step.
    return 2 * sizeof(shared::GBufferTexel) + 2 * sizeof(std::uint32_t) + 2 * sizeof(glm::vec4) +
           sizeof(std::uint32_t) + sizeof(glm::uvec4);
}

std::uint64_t Renderer::displayBytesPerPixel() {
    // resizeDisplay's buffers, the LDR image at that size and the resolve's keys (two of each).
    return 2 * sizeof(glm::vec4) + sizeof(std::uint32_t) + 2 * sizeof(std::uint32_t);
}

void Renderer::resizeDisplay(glm::uvec2 size, bool written) {
    if (mDisplaySize == size && (mDisplay[0].size() != 0) == written) return;
    mDisplaySize = size;
    const std::uint64_t pixels = std::uint64_t(size.x) * size.y;
    for (int i = 0; i < 2; ++i) {
        mDisplay[i] = written
                          ? gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::vec4),
                                        i ? "frame.display1" : "frame.display0")
                          : gpu::Buffer();
        // The resolve reads last frame's at its history taps as texels.
        if (written) mDisplay[i].setTexelFormat(VK_FORMAT_R32G32B32A32_SFLOAT);
    }
    mLdr = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(std::uint32_t), "frame.ldr");
}

void Renderer::resize(glm::uvec2 size) {
    if (mSize == size) return;
    mSize = size;
    const std::uint64_t pixels = std::uint64_t(size.x) * size.y;
    using gpu::BufferKind;
    for (int i = 0; i < 2; ++i) {
        mGBuffers[i] = gpu::Buffer(mCtx, BufferKind::Storage, pixels * sizeof(shared::GBufferTexel),
                                   i ? "frame.gbuffer1" : "frame.gbuffer0");
        // Passes that only read it fetch it as uvec4 texels (loadGBuffer): one gather per 16 B on
        // lavapipe, where a storage-buffer read at a lane-varying index loops over the lanes.
        mGBuffers[i].setTexelFormat(VK_FORMAT_R32G32B32A32_UINT);
        mSurfaceKeys[i] = gpu::Buffer(mCtx, BufferKind::Storage, pixels * sizeof(std::uint32_t),
                                      i ? "frame.surfaceKeys1" : "frame.surfaceKeys0");
        mSurfaceKeys[i].setTexelFormat(VK_FORMAT_R32_UINT);
    }
    mRadiance =
        gpu::Buffer(mCtx, BufferKind::Storage, pixels * sizeof(glm::vec4), "frame.radiance");
    mRadiance.setTexelFormat(VK_FORMAT_R32G32B32A32_SFLOAT);  // the resolve's taps
    mRayStats =
        gpu::Buffer(mCtx, BufferKind::Storage, pixels * sizeof(glm::uvec4), "frame.rayStats");
    mIndirect =
        gpu::Buffer(mCtx, BufferKind::Storage, pixels * sizeof(glm::vec4), "frame.indirect");
    resetHistory();
}

void Renderer::resetHistory() {
    mChanges.forgetHistory();
    mPrevTime.reset();
}

void Renderer::checkMemory(const world::Scene& scene, glm::uvec2 size, glm::uvec2 displaySize,
                           const lighting::LightingSettings& lighting) {
    if (mSize == size && mRequestedDisplay == displaySize && !mWorld.needsFullUpload(scene.grid))
        return;
    // About to allocate the frame's buffers or the world's GPU copy: refuse, with the plan, what
    // would not fit, before allocating any of it.
    const MemoryPlan memory = planMemory(scene, size, lighting, displaySize);
    if (Status s = checkMemoryPlan(memory, memoryBudgetBytes(), "world '" + scene.name + "'"); !s)
        throw MemoryBudgetExceeded(s.error().message);
    mRequestedDisplay = displaySize;
}

void Renderer::updateScene(world::Scene& scene, const FrameSettings& settings,
                           const lighting::LightingSettings& lighting, FrameResult& result) {
    // The emitter list reads the grid's touched cells before they are cleared.
    auto start = std::chrono::steady_clock::now();
    mEmitters.setSettings({lighting.brickLights});
    result.emitterUpdate = mEmitters.update(scene);
    result.emitterUpdateMs = msSince(start);
    result.emitters = mEmitters.aliveCount();
    // Objects at this frame's time; their previous pose is at the last frame's (this one's on a
    // first frame, like the camera), so motion vectors follow them.
    start = std::chrono::steady_clock::now();
    world::updateDynamicObjects(scene.objects, scene.dynamic, settings.timeSeconds,
                                mPrevTime.value_or(settings.timeSeconds));
    result.dynamicUpdateMs = msSince(start);
    mPrevTime = settings.timeSeconds;
}

void Renderer::prepareFrame(gpu::CommandList& cmd, world::Scene& scene, const FrameInput& in,
                            const FramePlan& plan, FrameResult& result) {
    cmd.beginPass("upload");
    result.upload = mWorld.sync(scene, mUploader);
    const EmitterUploadStats lightUpload = mGpuEmitters.sync(mEmitters, mUploader);
    const FrameChanges changes = mChanges.observe(
        {scene, in.camera, in.size, in.lighting, result.upload, result.emitterUpdate, lightUpload});
    scene.grid.clearDirty();  // every consumer has seen them (changes.editedCells)

    shared::FrameParams params = makeFrameParams(in.camera, scene.sky, in.settings);
    params.displaySize = glm::uvec4(in.displaySize, 0u, 0u);
    const shared::FrameParams prev =
        makeFrameParams(changes.previousCamera, scene.sky, in.settings);
    params.prevCameraPosition = prev.cameraPosition;
    params.prevCameraForward = prev.cameraForward;
    params.prevCameraRight = prev.cameraRight;
    params.prevCameraUp = prev.cameraUp;
    for (std::size_t i = 0; i < mTechniques.size(); ++i) {
        if (plan.steps[i].plan.runs)
            mTechniques[i]->prepare(changes, in, mUploader, params);
        else
            mTechniques[i]->skip();
    }
    mUploader.write(mFrameParams, 0, &params, sizeof(params));
    mUploader.record(cmd);
    if (!plan.addsIndirect) cmd.fillBuffer(mIndirect, 0);  // no technique writes the term
    cmd.endPass();
}

FrameResult Renderer::render(world::Scene& scene, const world::CameraPreset& camera,
                             const FrameSettings& settings,
                             const lighting::LightingSettings& requested,
                             gpu::Presenter* presenter) {
    const glm::uvec2 size(settings.width, settings.height);
    // The display's size if a technique resolves to it (the memory plan asks the frame plan).
    const glm::uvec2 requestedDisplay =
        settings.displayWidth != 0 ? glm::uvec2(settings.displayWidth, settings.displayHeight)
                                   : size;
    checkMemory(scene, size, requestedDisplay, requested);
    // Before the scene's update: a new size forgets the last frame's time, which the objects'
    // previous poses must not see after the update.
    resize(size);
    FrameResult result;
    updateScene(scene, settings, requested, result);
    const lighting::LightingSettings lighting =
        resolveAutoSampling(scene, requested, result.emitterUpdate);
    result.regirSampling = engine::lighting::usesRegir(lighting);
    const FramePlan frame = planFrame(lighting, sceneShape(scene), size);
    resizeDisplay(frame.writesDisplay ? requestedDisplay : size, frame.writesDisplay);
    // Every pass compiled without the code of the features this frame does not use.
    const std::span<const std::uint32_t> specialization =
        mSpecializeShaders ? std::span<const std::uint32_t>(frame.features)
                           : std::span<const std::uint32_t>();
    FrameCommands commands(mCtx, mTimer, mLateTimer, specialization);
    const FrameInput in{scene, camera,       settings,    lighting,
                        mSize, mDisplaySize, mFrameIndex, mEmitters.aliveCount()};
    prepareFrame(commands.current(), scene, in, frame, result);

    gpu::Buffer& gbuffer = mGBuffers[mCurrent];
    mPrimary.record(commands.current(), {mWorld, mFrameParams, gbuffer, mSurfaceKeys[mCurrent]},
                    mSize);
    const FrameBuffers buffers{{mWorld, mGpuEmitters},
                               mFrameParams,
                               gbuffer,
                               mGBuffers[mCurrent ^ 1u],
                               mSurfaceKeys[mCurrent],
                               mSurfaceKeys[mCurrent ^ 1u],
                               mRadiance,
                               mIndirect,
                               mRayStats,
                               mExposure,
                               mDisplay[mCurrent],
                               mLdr,
                               mDisplay[mCurrent ^ 1u],
                               mSize,
                               mDisplaySize,
                               mCurrent};
    for (std::size_t i = 0; i < mTechniques.size(); ++i) {
        if (frame.steps[i].plan.runs) mTechniques[i]->record(commands, buffers);
    }
    // A technique that writes the display tonemaps it too (TechniquePlan::writesDisplay).
    if (!frame.writesDisplay)
        mTonemap.record(commands.current(), {mFrameParams, mRadiance, mLdr, mExposure},
                        mDisplaySize);
    commands.finish();
    result.passMs = commands.passMs();
    for (std::size_t i = 0; i < mTechniques.size(); ++i) {
        if (frame.steps[i].plan.runs) mTechniques[i]->collect(result);
    }

    mCurrent ^= 1u;
    ++mFrameIndex;
    if (presenter) present(*presenter, result);
    return result;
}

lighting::LightingSettings Renderer::resolveAutoSampling(
    const world::Scene& scene, const lighting::LightingSettings& lighting,
    const lighting::EmitterUpdateStats& update) {
    if (!lighting.autoSampling) return lighting;
    const glm::ivec3 world = scene.grid.sizeInVoxels();
    const bool emittersChanged =
        update.full || update.added != 0 || update.removed != 0 || update.changed != 0;
    if (!mSamplingFacts || emittersChanged || world != mSamplingFactsWorld ||
        !(lighting.regir == mSamplingFactsKnobs)) {
        mSamplingFacts = engine::render::samplingFacts(mEmitters, world, lighting.regir);
        mSamplingFactsWorld = world;
        mSamplingFactsKnobs = lighting.regir;
    }
    return resolveSampling(lighting, autoChoosesRegir(*mSamplingFacts));
}

void Renderer::present(gpu::Presenter& presenter, FrameResult& result) {
    // A submission of its own, so only this pass waits for the swapchain image. The barrier that
    // ends the frame's submission orders the LDR writes before the copy.
    gpu::CommandList cmd(mCtx, &mPresentTimer);
    cmd.begin();
    presenter.record(cmd, mLdr, mDisplaySize);
    cmd.submitAndWait(presenter.submitSync());
    presenter.endFrame();
    for (const auto& pass : mPresentTimer.results()) result.passMs.push_back(pass);
}

FrameImages Renderer::readback() {
    FrameImages images;
    images.width = mSize.x;
    images.height = mSize.y;
    const gpu::Buffer& gbuffer = mGBuffers[mCurrent ^ 1u];  // the last rendered frame's
    const bool resolved = mDisplay[0].size() != 0;
    const gpu::Buffer& display = resolved ? mDisplay[mCurrent ^ 1u] : mRadiance;
    const gpu::Buffer* sources[] = {&mRadiance, &mLdr, &gbuffer, &mRayStats, &mIndirect, &display};
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
    take(images.display, display, at);
    images.displayWidth = mDisplaySize.x;
    images.displayHeight = mDisplaySize.y;
    return images;
}

}  // namespace engine::render
