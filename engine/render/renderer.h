// Renderer: owns the frame. Each frame:
//   pose dynamic objects at the frame's scene time and re-voxelise them (CPU)
//   upload (dirty bricks, the dynamic grid if it changed, changed emitters, frame constants)
//   -> primary_rays (G-buffer with motion vectors)
//   -> lighting: preview shading | ReSTIR (initial, temporal, spatial, shade) | RIS | light
//      sampling | brute force | reference path tracing (accumulates while nothing changes)
//   -> indirect term, added to the radiance: the irradiance cache, path-traced bounces or voxel
//      cone tracing (inject the radiance clipmap, then cones per pixel)
//   -> tonemap
// with a GPU timestamp per pass. Temporal state (G-buffers and reservoirs of the previous frame)
// ping-pongs between two buffers; a change of image size or method drops it. Given a
// gpu::Presenter, a "present" pass then puts the LDR image in a window (its own submission,
// timed like the others).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/timestamp_timer.h"
#include "gpu/uploader.h"
#include "lighting/emitter_list.h"
#include "render/gpu_emitter_list.h"
#include "lighting/lighting_settings.h"
#include "render/camera.h"
#include "render/gpu_world.h"
#include "render/baselines/light_sampling_pass.h"
#include "render/dvf_sky/dvf_sky.h"
#include "render/irradiance_cache/irradiance_cache.h"
#include "render/light_tiles/light_tiles.h"
#include "render/passes/primary_ray_pass.h"
#include "render/path_indirect/path_indirect.h"
#include "render/vct/voxel_cone_tracing.h"
#include "render/passes/sun_shade_pass.h"
#include "render/passes/tonemap_pass.h"
#include "render/reference/reference_pass.h"
#include "render/regir/regir_grid.h"
#include "render/restir/restir_initial_pass.h"
#include "render/restir/restir_shade_pass.h"
#include "render/restir/restir_spatial_pass.h"
#include "render/restir/restir_temporal_pass.h"
#include "shared/gbuffer.h"

namespace engine::gpu {
class Presenter;
}

namespace engine::render {

struct FrameResult {
    std::vector<std::pair<std::string, double>> passMs;  // GPU milliseconds per pass, in order
    WorldUploadStats upload;
    lighting::EmitterUpdateStats emitterUpdate;
    double emitterUpdateMs = 0.0;  // CPU time of the emitter list update
    double dynamicUpdateMs = 0.0;  // CPU time of posing and re-voxelising dynamic objects
    std::uint32_t emitters = 0;
    std::uint32_t referenceSamples = 0;  // samples per pixel accumulated so far (reference)
    bool cacheUsed = false;
    bool cacheSplitFrame = false;  // the cache had no visible set yet: two submissions, the G-buffer read in between
    double cachePrepareMs = 0.0;   // CPU time of the cache's directory and uploads
    IrradianceCacheStats cache;
    bool skyUsed = false;  // a sky term (DVF or its reference) was added
    DvfSkyStats sky;       // DVF: masks held, queued and traced this frame
    double totalMs() const;
    double passMsOf(const std::string& name) const;
};

struct FrameImages {
    std::uint32_t width = 0, height = 0;
    std::vector<glm::vec4> radiance;  // linear
    std::vector<std::uint32_t> rgba8;  // tonemapped sRGB, R in the low byte
    std::vector<shared::GBufferTexel> gbuffer;
    std::vector<glm::uvec4> rayStats;  // preview only: x primary steps, y shadow steps, z rays
    std::vector<glm::vec4> indirect;   // the indirect term alone: the cache's or the path tracer's (zero without one)
};

class Renderer {
public:
    explicit Renderer(gpu::Context& ctx);
    // Device bytes of the buffers the renderer keeps per pixel (G-buffers, reservoirs, radiance…).
    static std::uint64_t frameBytesPerPixel();

    // `presenter`, when given, must have begun its frame (Presenter::beginFrame); the frame is
    // presented before this returns.
    FrameResult render(world::Scene& scene, const world::CameraPreset& camera, const FrameSettings& settings,
                       const lighting::LightingSettings& lighting = {}, gpu::Presenter* presenter = nullptr);
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
    const IrradianceCache& irradianceCache() const { return mCache; }
    const LightTiles& lightTiles() const { return mLightTiles; }
    const RegirGrid& regirGrid() const { return mRegir; }
    DvfSky& dvfSky() { return mDvfSky; }

private:
    void resize(std::uint32_t width, std::uint32_t height);
    // Uploads the parameters of the frame's lighting method (its module's one packing function).
    void writeMethodParams(const lighting::LightingSettings& lighting);
    void recordLighting(gpu::CommandList& cmd, const lighting::LightingSettings& lighting, bool historyValid);

    gpu::Context& mCtx;
    GpuWorld mWorld;
    lighting::EmitterList mEmitters;
    GpuEmitterList mGpuEmitters;
    gpu::Uploader mUploader;
    // The cache's uploads, recorded while the frame's first submission may still read mUploader's
    // staging memory.
    gpu::Uploader mCacheUploader;
    gpu::TimestampTimer mTimer;
    gpu::TimestampTimer mPresentTimer;
    gpu::TimestampTimer mLateTimer;  // the cache frame's second submission
    PrimaryRayPass mPrimary;
    SunShadePass mPreview;
    RestirInitialPass mRestirInitial;
    RestirTemporalPass mRestirTemporal;
    RestirSpatialPass mRestirSpatial;
    RestirShadePass mRestirShade;
    LightSamplingPass mLightSampling;
    ReferencePass mReference;
    TonemapPass mTonemap;
    IrradianceCache mCache;
    LightTiles mLightTiles;
    RegirGrid mRegir;
    PathIndirect mPathIndirect;
    DvfSky mDvfSky;
    std::optional<glm::vec4> mPrevDynamicBounds;  // the objects' last bounding sphere, for the sky's masks
    VoxelConeTracing mVct;

    glm::uvec2 mSize{0};
    gpu::Buffer mFrameParams, mRadiance, mLdr, mRayStats, mCandidates, mOwnReservoirs, mAccumulation, mIndirect;
    gpu::Buffer mRestirParams, mLightSamplingParams, mReferenceParams;  // each method module's parameters
    // The last frame's G-buffer on the host: the cache's visible voxels for the next frame.
    gpu::Buffer mGBufferHost;
    bool mGBufferHostValid = false;
    std::optional<world::SkyLight> mPrevSky;  // the cache restarts its entries when the sun or sky changes
    gpu::Buffer mGBuffers[2], mFinalReservoirs[2];
    std::uint32_t mCurrent = 0;  // which of the ping-pong pair is this frame's
    std::uint32_t mFrameIndex = 0;
    bool mSpecializeShaders = true;
    bool mHistoryValid = false;
    std::optional<world::CameraPreset> mPrevCamera;
    std::optional<double> mPrevTime;  // last frame's scene time, for the objects' motion vectors
    std::optional<lighting::LightingSettings> mPrevLighting;
    std::uint32_t mAccumulatedSamples = 0;
};

}  // namespace engine::render
