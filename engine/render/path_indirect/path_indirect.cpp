#include "render/path_indirect/path_indirect.h"

#include <algorithm>
#include <fmt/format.h>

#include "render/frame_commands.h"

namespace engine::render {

PathIndirect::PathIndirect(gpu::Context& ctx) : mCtx(ctx), mPass(ctx) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::PathIndirectParams),
                          "path.params");
}

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
    shared::PathIndirectParams p{};
    p.samples = std::max(lighting.path.samples, 1u);
    p.bounces = std::max(lighting.path.bounces, 1u);
    p.flags = (lighting.brickLights ? shared::PATH_INDIRECT_BRICK_LIGHTS : 0u) |
              (restart ? shared::PATH_INDIRECT_RESTART : 0u);
    p.frame = in.frameIndex;
    p.seed = lighting.seed;
    uploader.write(mParams, 0, &p, sizeof(p));
    mPaths = (restart ? 0u : mPaths) + p.samples;
}

void PathIndirect::record(FrameCommands& commands, const FrameBuffers& frame) {
    mPass.record(
        commands.current(), frame.scene,
        {frame.frameParams, mParams, frame.gbuffer, mAccumulation, frame.indirect, frame.radiance},
        mSize);
}

}  // namespace engine::render
