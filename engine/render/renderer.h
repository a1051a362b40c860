// Renderer: owns the frame. Each frame:
//   pose dynamic objects at the frame's scene time and re-voxelise them (CPU)
//   plan the frame (frame_plan.h: which techniques run, their shader features and memory)
//   upload (dirty bricks, the dynamic grid if it changed, changed emitters), work out what
//   changed since the last frame (frame_changes.h), let each planned technique prepare, upload
//   the frame constants
//   -> primary_rays (G-buffer with motion vectors)
//   -> each planned technique's passes, in registry order (technique_registry.cpp): light tiles
//      and ReGIR, the direct light (preview | ReSTIR/RIS | baselines | reference), then the terms
//      added to it (sky, path-traced or cone-traced indirect light, the irradiance cache)
//   -> tonemap
// with a GPU timestamp per pass. The G-buffer ping-pongs between two buffers, so temporal
// passes read the last frame's. Given a gpu::Presenter, a "present" pass then puts the LDR image
// in a window (its own submission, timed like the others).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/timestamp_timer.h"
#include "gpu/uploader.h"
#include "lighting/emitter_list.h"
#include "lighting/lighting_settings.h"
#include "render/camera.h"
#include "render/frame_changes.h"
#include "render/frame_result.h"
#include "render/gpu_emitter_list.h"
#include "render/gpu_world.h"
#include "render/passes/primary_ray_pass.h"
#include "render/passes/tonemap_pass.h"
#include "render/sampling_choice.h"
#include "render/technique.h"
#include "shared/gbuffer.h"

namespace engine::gpu {
class Presenter;
}

namespace engine::render {

class DvfSky;
class IrradianceCache;
class LightTiles;
class RegirGrid;
class TemporalUpsampling;
struct FramePlan;

struct FrameImages {
    std::uint32_t width = 0, height = 0;
    std::vector<glm::vec4> radiance;   // linear
    std::vector<std::uint32_t> rgba8;  // tonemapped sRGB, R in the low byte
    std::vector<shared::GBufferTexel> gbuffer;
    std::vector<glm::uvec4> rayStats;  // preview only: x primary steps, y shadow steps, z rays
    std::vector<glm::vec4>
        indirect;  // the indirect term alone: the cache's or the path tracer's (zero without one)
    // What the display shows, at its size: `rgba8` (tonemapped) and `display` (linear, before
    // exposure). Without a reconstruction the render size, and `display` is `radiance`.
    std::uint32_t displayWidth = 0, displayHeight = 0;
    std::vector<glm::vec4> display;
};

class Renderer {
public:
    explicit Renderer(gpu::Context& ctx);
    ~Renderer();
    // Device bytes of the buffers the frame itself keeps per pixel (G-buffers, radiance, …); each
    // technique's own are in its plan (TechniquePlan::deviceBytes).
    static std::uint64_t frameBytesPerPixel();
    // The same per display pixel when a technique resolves the image to the display's size.
    static std::uint64_t displayBytesPerPixel();

    // `presenter`, when given, must have begun its frame (Presenter::beginFrame); the frame is
    // presented before this returns.
    // `settings.displayWidth/Height` size the displayed image when the lighting reconstructs it
    // (lighting::reconstructs); the LDR image and the presented one are at that size.
    FrameResult render(world::Scene& scene, const world::CameraPreset& camera,
                       const FrameSettings& settings,
                       const lighting::LightingSettings& lighting = {},
                       gpu::Presenter* presenter = nullptr);
    // Copies the last frame's buffers back to the host.
    FrameImages readback();
    // Forget temporal history and accumulated reference samples.
    void resetHistory();
    // The frame index the next frame renders with (it seeds all randomness, then counts up).
    // A capture sets it to the capture's own frame number so a slice rendered on another
    // machine draws the same random numbers for the same frame.
    void setFrameIndex(std::uint32_t index) { mFrameIndex = index; }
    // Off: every pass runs its generic code, nothing compiled out (render/shader_features.h);
    // the images must be the same, which is how the tests check what is compiled out.
    void setSpecializeShaders(bool on) { mSpecializeShaders = on; }

    GpuWorld& gpuWorld() { return mWorld; }
    const lighting::EmitterList& emitters() const { return mEmitters; }
    // What --sampling auto last chose from (none before a frame with sampling auto).
    const std::optional<SamplingFacts>& samplingFacts() const { return mSamplingFacts; }
    // The techniques, for tests and tools that read their state.
    const IrradianceCache& irradianceCache() const;
    const LightTiles& lightTiles() const;
    const RegirGrid& regirGrid() const;
    const TemporalUpsampling& temporalUpsampling() const;
    DvfSky& dvfSky();

private:
    // Refuses, before allocating any of it, a frame whose buffers or world would not fit.
    void checkMemory(const world::Scene& scene, glm::uvec2 size, glm::uvec2 displaySize,
                     const lighting::LightingSettings& lighting);
    void resize(glm::uvec2 size);
    // The display image's buffers: at `size` when a technique writes it, else none.
    void resizeDisplay(glm::uvec2 size, bool written);
    // The emitter list and the dynamic objects brought up to this frame, on the host.
    void updateScene(world::Scene& scene, const FrameSettings& settings,
                     const lighting::LightingSettings& lighting, FrameResult& result);
    // The uploads, what changed, each running technique's host work; recorded into `cmd`.
    void prepareFrame(gpu::CommandList& cmd, world::Scene& scene, const FrameInput& in,
                      const FramePlan& plan, FrameResult& result);
    void present(gpu::Presenter& presenter, FrameResult& result);
    // The lighting with --sampling auto resolved for this scene (render/sampling_choice.h); the
    // facts are gathered again only when the emitters, the world's size or ReGIR's knobs change.
    lighting::LightingSettings resolveAutoSampling(const world::Scene& scene,
                                                   const lighting::LightingSettings& lighting,
                                                   const lighting::EmitterUpdateStats& update);
    template <class T>
    T& technique(std::string_view name) const;

    gpu::Context& mCtx;
    GpuWorld mWorld;
    lighting::EmitterList mEmitters;
    GpuEmitterList mGpuEmitters;
    gpu::Uploader mUploader;
    gpu::TimestampTimer mTimer;
    gpu::TimestampTimer mPresentTimer;
    gpu::TimestampTimer mLateTimer;  // a frame's second submission (FrameCommands)
    PrimaryRayPass mPrimary;
    TonemapPass mTonemap;
    // One per registered technique, in registry order.
    std::vector<std::unique_ptr<Technique>> mTechniques;
    FrameChangeTracker mChanges;
    std::optional<SamplingFacts> mSamplingFacts;  // for --sampling auto, with what it was made of
    glm::ivec3 mSamplingFactsWorld{0};
    shared::RegirKnobs mSamplingFactsKnobs{};

    glm::uvec2 mSize{0};
    gpu::Buffer mFrameParams, mRadiance, mLdr, mRayStats, mIndirect;
    gpu::Buffer mExposure;  // shared::ExposureState: the tonemap's exposure when it is automatic
    gpu::Buffer mGBuffers[2];
    gpu::Buffer mSurfaceKeys[2];  // each G-buffer's surface keys (uint per pixel)
    glm::uvec2 mDisplaySize{0};
    glm::uvec2 mRequestedDisplay{0};  // the display size the memory was last checked for
    gpu::Buffer mDisplay[2];     // the display image and last frame's, when a technique writes it
    std::uint32_t mCurrent = 0;  // which of the ping-pong pair is this frame's
    std::uint32_t mFrameIndex = 0;
    bool mSpecializeShaders = true;
    std::optional<double> mPrevTime;  // last frame's scene time, for the objects' motion vectors
};

}  // namespace engine::render
