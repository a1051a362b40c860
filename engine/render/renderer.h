// Renderer: owns the frame. Each frame: upload what changed in the world, then
//   primary_rays -> shade_sun -> tonemap
// with a GPU timestamp per pass. Frame buffers (G-buffer, radiance, LDR, ray statistics) are
// sized to the requested image and kept between frames. Later lighting passes slot in between
// primary rays and tonemapping (docs/ARCHITECTURE.md).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/timestamp_timer.h"
#include "gpu/uploader.h"
#include "render/camera.h"
#include "render/gpu_world.h"
#include "render/passes/primary_ray_pass.h"
#include "render/passes/sun_shade_pass.h"
#include "render/passes/tonemap_pass.h"
#include "shared/gbuffer.h"

namespace engine::render {

struct FrameResult {
    std::vector<std::pair<std::string, double>> passMs;  // GPU milliseconds per pass, in order
    WorldUploadStats upload;
    double totalMs() const;
};

struct FrameImages {
    std::uint32_t width = 0, height = 0;
    std::vector<glm::vec4> radiance;  // linear
    std::vector<std::uint32_t> rgba8;  // tonemapped sRGB, R in the low byte
    std::vector<shared::GBufferTexel> gbuffer;
    std::vector<glm::uvec4> rayStats;  // x primary steps, y shadow steps, z rays
};

class Renderer {
public:
    explicit Renderer(gpu::Context& ctx);

    FrameResult render(world::Scene& scene, const world::CameraPreset& camera, const FrameSettings& settings);
    // Copies the last frame's buffers back to the host.
    FrameImages readback();

    GpuWorld& gpuWorld() { return mWorld; }

private:
    void resize(std::uint32_t width, std::uint32_t height);

    gpu::Context& mCtx;
    GpuWorld mWorld;
    gpu::Uploader mUploader;
    gpu::TimestampTimer mTimer;
    PrimaryRayPass mPrimary;
    SunShadePass mShade;
    TonemapPass mTonemap;
    glm::uvec2 mSize{0};
    gpu::Buffer mFrameParams, mGBuffer, mRadiance, mLdr, mRayStats;
};

}  // namespace engine::render
