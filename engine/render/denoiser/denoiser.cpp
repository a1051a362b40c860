#include "render/denoiser/denoiser.h"

#include <algorithm>
#include <fmt/format.h>

#include "gpu/uploader.h"
#include "render/frame_commands.h"

namespace engine::render {

namespace {

// Per pixel: the history and moments (two of each), and the a-trous ping-pong pair.
constexpr std::uint64_t kBytesPerPixel =
    2 * sizeof(glm::vec4) + 2 * sizeof(glm::vec2) + 2 * sizeof(glm::vec4);

}  // namespace

Denoiser::Denoiser(gpu::Context& ctx) : mCtx(ctx), mTemporal(ctx), mAtrous(ctx) {
    for (std::uint32_t i = 0; i <= kMaxPasses; ++i)
        mParams.emplace_back(ctx, gpu::BufferKind::Storage, sizeof(shared::DenoiserParams),
                             "denoise.params");
}

TechniquePlan Denoiser::plan(const lighting::LightingSettings& l, const SceneShape&,
                             glm::uvec2 size) {
    TechniquePlan p;
    p.runs = lighting::denoises(l);
    p.deviceBytes = (kMaxPasses + 1) * sizeof(shared::DenoiserParams) +
                    std::uint64_t(size.x) * size.y * kBytesPerPixel;
    return p;
}

std::string Denoiser::describe(const lighting::LightingSettings& l) {
    return fmt::format("denoised over up to {} frames, {} a-trous passes", l.display.denoiseHistory,
                       l.display.denoisePasses);
}

void Denoiser::prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                       shared::FrameParams&) {
    if (in.size != mSize) {
        mSize = in.size;
        const std::uint64_t pixels = std::uint64_t(mSize.x) * mSize.y;
        for (int i = 0; i < 2; ++i) {
            mHistory[i] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::vec4),
                                      "denoise.history");
            mMoments[i] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::vec2),
                                      "denoise.moments");
            mFiltered[i] = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::vec4),
                                       "denoise.filtered");
            // The passes read them at their taps as texels (shaders/denoiser/).
            mHistory[i].setTexelFormat(VK_FORMAT_R32G32B32A32_SFLOAT);
            mMoments[i].setTexelFormat(VK_FORMAT_R32G32_SFLOAT);
            mFiltered[i].setTexelFormat(VK_FORMAT_R32G32B32A32_SFLOAT);
        }
        mRestart = true;
    }
    // What the history cannot follow pixel by pixel: the light itself changed. (A moving camera
    // or object is followed by the motion vectors.)
    const bool lightingChanged = changes.historyLost || changes.staticWorldChanged ||
                                 changes.lightsUploaded || changes.skyChanged ||
                                 changes.settingsChanged;
    const lighting::DisplaySettings& d = in.lighting.display;
    mPasses = std::clamp(d.denoisePasses, 1u, kMaxPasses);
    shared::DenoiserParams temporal{};
    temporal.flags = mRestart || lightingChanged ? shared::DENOISER_RESTART : 0u;
    temporal.maxHistory = std::max(d.denoiseHistory, 1u);
    uploader.write(mParams[0], 0, &temporal, sizeof(temporal));
    for (std::uint32_t i = 0; i < mPasses; ++i) {
        shared::DenoiserParams atrous{};
        atrous.flags = i + 1 == mPasses ? shared::DENOISER_LAST : 0u;
        atrous.step = 1u << i;
        uploader.write(mParams[i + 1], 0, &atrous, sizeof(atrous));
    }
    mRestart = false;
}

void Denoiser::record(FrameCommands& commands, const FrameBuffers& frame) {
    gpu::CommandList& cmd = commands.current();
    const std::uint32_t now = frame.parity, then = frame.parity ^ 1u;
    mTemporal.record(
        cmd, frame.scene,
        {frame.frameParams, mParams[0], frame.gbuffer, frame.prevSurfaceKeys, frame.radiance,
         mHistory[then], mHistory[now], mMoments[then], mMoments[now], mFiltered[0]},
        frame.size);
    for (std::uint32_t i = 0; i < mPasses; ++i) {
        mAtrous.record(cmd, frame.scene,
                       {frame.frameParams, mParams[i + 1], frame.gbuffer, frame.radiance,
                        mFiltered[i % 2], mFiltered[(i + 1) % 2], frame.surfaceKeys},
                       frame.size);
    }
}

}  // namespace engine::render
