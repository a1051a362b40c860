#include "render/exposure/auto_exposure.h"

#include <fmt/format.h>

#include "gpu/command_list.h"
#include "gpu/uploader.h"
#include "render/frame_commands.h"

namespace engine::render {

AutoExposure::AutoExposure(gpu::Context& ctx) : mHistogramPass(ctx), mAdaptPass(ctx) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::ExposureParams),
                          "exposure.params");
    mHistogram = gpu::Buffer(ctx, gpu::BufferKind::Storage,
                             shared::EXPOSURE_BINS * sizeof(std::uint32_t), "exposure.histogram");
}

TechniquePlan AutoExposure::plan(const lighting::LightingSettings& l, const SceneShape&,
                                 glm::uvec2) {
    TechniquePlan p;
    p.runs = lighting::usesAutoExposure(l);
    p.deviceBytes = sizeof(shared::ExposureParams) + shared::EXPOSURE_BINS * sizeof(std::uint32_t);
    return p;
}

std::string AutoExposure::describe(const lighting::LightingSettings& l) {
    return fmt::format("auto exposure key {} adapting {}/frame", l.exposure.key,
                       l.exposure.adaptation);
}

void AutoExposure::prepare(const FrameChanges& changes, const FrameInput& in,
                           gpu::Uploader& uploader, shared::FrameParams& params) {
    const lighting::ExposureSettings& e = in.lighting.exposure;
    shared::ExposureParams p{};
    p.key = e.key;
    p.adaptation = e.adaptation;
    p.restart = mRestart || changes.historyLost ? 1u : 0u;
    p.lowPercentile = 0.5f;  // the brighter half of the lit pixels, without the brightest 5 %
    p.highPercentile = 0.95f;
    p.minLog2 = -12.0f;
    p.maxLog2 = 12.0f;
    uploader.write(mParams, 0, &p, sizeof(p));
    params.exposure.y = 1.0f;  // the tonemap reads the state's exposure
    mClearState = p.restart != 0u;
    mRestart = false;
}

void AutoExposure::record(FrameCommands& commands, const FrameBuffers& frame) {
    gpu::CommandList& cmd = commands.current();
    cmd.fillBuffer(mHistogram, 0);
    if (mClearState) cmd.fillBuffer(frame.exposure, 0);
    const ExposureIo io{frame.frameParams, mParams, frame.radiance, mHistogram, frame.exposure};
    mHistogramPass.record(cmd, io, frame.size);
    mAdaptPass.record(cmd, io);
}

}  // namespace engine::render
