#include "render/path_indirect/path_indirect.h"

#include <algorithm>
#include <fmt/format.h>

#include "render/frame_commands.h"
#include "render/loop_budget.h"

namespace engine::render {

PathIndirect::PathIndirect(gpu::Context& ctx) : mCtx(ctx), mPass(ctx) {}

TechniquePlan PathIndirect::plan(const lighting::LightingSettings& l, const SceneShape&,
                                 glm::uvec2 size) {
    TechniquePlan p;
    p.runs = lighting::usesPath(l);
    p.addsIndirect = true;
    p.deviceBytes =
        sizeof(shared::PathIndirectParams) + std::uint64_t(size.x) * size.y * sizeof(glm::vec4);
    return p;
}

std::string PathIndirect::describe(const lighting::LightingSettings& l) {
    return fmt::format("path {} spp {} bounce(s){}", l.path.samples, l.path.bounces,
                       l.path.accumulate ? " accumulated" : "");
}

void PathIndirect::prepare(const FrameChanges& changes, const FrameInput& in,
                           gpu::Uploader& uploader, shared::FrameParams&) {
    const lighting::LightingSettings& lighting = in.lighting;
    bool restart = changes.restartsAccumulation();
    if (in.size != mSize) {
        mSize = in.size;
        mAccumulation =
            gpu::Buffer(mCtx, gpu::BufferKind::Storage,
                        std::uint64_t(mSize.x) * mSize.y * sizeof(glm::vec4), "path.accumulation");
        restart = true;
    }
    restart = restart || !lighting.path.accumulate || mPaths == 0;
    const std::uint32_t samples = std::max(lighting.path.samples, 1u);
    shared::PathIndirectParams p{};
    p.bounces = std::max(lighting.path.bounces, 1u);
    p.frame = in.frameIndex;
    p.seed = lighting.seed;
    // A path from the G-buffer is a reference sample without its camera ray: the same bound.
    const std::uint32_t perDispatch = referenceSamplesPerDispatch(in.scene, p.bounces);
    mDispatches = (samples + perDispatch - 1) / perDispatch;
    while (mParams.size() < mDispatches)
        mParams.emplace_back(mCtx, gpu::BufferKind::Storage, sizeof(shared::PathIndirectParams),
                             "path.params");
    for (std::uint32_t d = 0; d < mDispatches; ++d) {
        p.firstSample = d * perDispatch;
        p.samples = std::min(perDispatch, samples - p.firstSample);
        p.flags = (lighting.brickLights ? shared::PATH_INDIRECT_BRICK_LIGHTS : 0u) |
                  (restart && d == 0 ? shared::PATH_INDIRECT_RESTART : 0u) |
                  (d + 1 == mDispatches ? shared::PATH_INDIRECT_FINAL : 0u);
        uploader.write(mParams[d], 0, &p, sizeof(p));
    }
    mPaths = (restart ? 0u : mPaths) + samples;
}

void PathIndirect::record(FrameCommands& commands, const FrameBuffers& frame) {
    std::vector<PathIndirectIo> series;
    for (std::uint32_t d = 0; d < mDispatches; ++d)
        series.push_back({frame.frameParams, mParams[d], frame.gbuffer, mAccumulation,
                          frame.indirect, frame.radiance});
    mPass.recordSeries(commands.current(), frame.scene, series, mSize);
}

}  // namespace engine::render
