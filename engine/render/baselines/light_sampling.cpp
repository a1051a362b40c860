#include "render/baselines/light_sampling.h"

#include <fmt/format.h>

#include "gpu/uploader.h"
#include "render/baselines/light_sampling_params.h"
#include "render/frame_commands.h"

namespace engine::render {

LightSampling::LightSampling(gpu::Context& ctx) : mPass(ctx) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::LightSamplingParams),
                          "baselines.params");
}

TechniquePlan LightSampling::plan(const lighting::LightingSettings& l, const SceneShape&,
                                  glm::uvec2) {
    TechniquePlan p;
    p.runs = lighting::samplesLightsPerPixel(l);
    p.deviceBytes = sizeof(shared::LightSamplingParams);
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
    const shared::LightSamplingParams p = lightSamplingParams(in.lighting, in.frameIndex);
    uploader.write(mParams, 0, &p, sizeof(p));
}

void LightSampling::record(FrameCommands& commands, const FrameBuffers& frame) {
    mPass.record(commands.current(), frame.scene,
                 {frame.frameParams, mParams, frame.gbuffer, frame.radiance}, frame.size);
}

}  // namespace engine::render
