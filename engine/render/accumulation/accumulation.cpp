#include "render/accumulation/accumulation.h"

#include <algorithm>
#include <fmt/format.h>

#include "gpu/uploader.h"
#include "render/frame_commands.h"
#include "render/frame_result.h"

namespace engine::render {

Accumulation::Accumulation(gpu::Context& ctx) : mCtx(ctx), mPass(ctx) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::AccumulationParams),
                          "accumulation.params");
}

TechniquePlan Accumulation::plan(const lighting::LightingSettings& l, const SceneShape&,
                                 glm::uvec2 size) {
    TechniquePlan p;
    p.runs = lighting::accumulates(l);
    p.deviceBytes =
        sizeof(shared::AccumulationParams) + std::uint64_t(size.x) * size.y * sizeof(glm::vec4);
    return p;
}

std::string Accumulation::describe(const lighting::LightingSettings& l) {
    return fmt::format("accumulated over up to {} still frames", l.accumulation.frames);
}

void Accumulation::prepare(const FrameChanges& changes, const FrameInput& in,
                           gpu::Uploader& uploader, shared::FrameParams&) {
    if (in.size != mSize) {
        mSize = in.size;
        mHistory = gpu::Buffer(mCtx, gpu::BufferKind::Storage,
                               std::uint64_t(mSize.x) * mSize.y * sizeof(glm::vec4),
                               "accumulation.history");
        mFrames = 0;
    }
    if (changes.restartsAccumulation()) mFrames = 0;
    mFrames = std::min(mFrames + 1u, std::max(in.lighting.accumulation.frames, 1u));
    const shared::AccumulationParams p{mFrames, 0, 0, 0};
    uploader.write(mParams, 0, &p, sizeof(p));
}

void Accumulation::record(FrameCommands& commands, const FrameBuffers& frame) {
    mPass.record(commands.current(), {frame.frameParams, mParams, mHistory, frame.radiance}, mSize);
}

void Accumulation::collect(FrameResult& result) { result.accumulatedFrames = mFrames; }

}  // namespace engine::render
