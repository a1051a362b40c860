#include "render/baselines/light_sampling.h"

#include <fmt/format.h>

#include "gpu/uploader.h"
#include "render/baselines/light_sampling_params.h"
#include "render/frame_commands.h"
#include "render/loop_budget.h"
#include "world/scene.h"

namespace engine::render {

LightSampling::LightSampling(gpu::Context& ctx) : mCtx(ctx), mPass(ctx) {
    mPartial = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(glm::uvec4), "baselines.partial");
}

TechniquePlan LightSampling::plan(const lighting::LightingSettings& l, const SceneShape&,
                                  glm::uvec2 size) {
    TechniquePlan p;
    p.runs = lighting::samplesLightsPerPixel(l);
    p.deviceBytes = sizeof(shared::LightSamplingParams);
    // The running sums of a frame split across dispatches (render/loop_budget.h).
    p.deviceBytes += std::uint64_t(size.x) * size.y * sizeof(glm::uvec4);
    return p;
}

std::string LightSampling::describe(const lighting::LightingSettings& l) {
    const char* mode = l.area ? "area" : "point";
    if (l.method == lighting::Method::BruteForce) return fmt::format("bruteforce {}", mode);
    return fmt::format("uniform {} {} rays {} {}", mode, l.shadowRays,
                       l.byPower ? "power" : "uniform", l.brickLights ? "bricks" : "voxels");
}

void LightSampling::prepare(const FrameChanges&, const FrameInput& in, gpu::Uploader& uploader,
                            shared::FrameParams&) {
    shared::LightSamplingParams p = lightSamplingParams(in.lighting, in.frameIndex);
    const std::uint32_t rays = p.everyLight != 0u ? in.emitters : std::max(p.samples, 1u);
    const std::uint32_t perDispatch = in.lighting.shadowRaysPerDispatch != 0u
                                          ? in.lighting.shadowRaysPerDispatch
                                          : shadowRaysPerDispatch(in.scene);
    mDispatches = std::max(1u, (rays + perDispatch - 1u) / perDispatch);
    const std::uint64_t partialBytes =
        mDispatches > 1u ? std::uint64_t(in.size.x) * in.size.y * sizeof(glm::uvec4)
                         : sizeof(glm::uvec4);
    if (mPartial.size() != partialBytes)
        mPartial = gpu::Buffer(mCtx, gpu::BufferKind::Storage, partialBytes, "baselines.partial");
    while (mParams.size() < mDispatches)
        mParams.emplace_back(mCtx, gpu::BufferKind::Storage, sizeof(shared::LightSamplingParams),
                             "baselines.params");
    for (std::uint32_t d = 0; d < mDispatches; ++d) {
        p.first = d * perDispatch;
        p.end = d + 1 < mDispatches ? p.first + perDispatch : shared::LIGHT_SAMPLING_REST;
        uploader.write(mParams[d], 0, &p, sizeof(p));
    }
}

void LightSampling::record(FrameCommands& commands, const FrameBuffers& frame) {
    std::vector<LightSamplingIo> series;
    for (std::uint32_t d = 0; d < mDispatches; ++d)
        series.push_back({frame.frameParams, mParams[d], frame.gbuffer, frame.radiance, mPartial});
    mPass.recordSeries(commands.current(), frame.scene, series, frame.size);
}

}  // namespace engine::render
