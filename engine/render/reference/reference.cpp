#include "render/reference/reference.h"

#include <algorithm>
#include <fmt/format.h>

#include "gpu/command_list.h"
#include "gpu/uploader.h"
#include "render/frame_commands.h"
#include "render/frame_result.h"
#include "render/loop_budget.h"
#include "render/reference/reference_params.h"

namespace engine::render {

Reference::Reference(gpu::Context& ctx) : mCtx(ctx), mPass(ctx) {}

TechniquePlan Reference::plan(const lighting::LightingSettings& l, const SceneShape&,
                              glm::uvec2 size) {
    TechniquePlan p;
    p.runs = l.method == lighting::Method::Reference;
    p.deviceBytes =
        sizeof(shared::ReferenceParams) + std::uint64_t(size.x) * size.y * sizeof(glm::vec4);
    return p;
}

std::string Reference::describe(const lighting::LightingSettings& l) {
    return fmt::format("reference {} bounce(s)", l.bounces);
}

void Reference::prepare(const FrameChanges& changes, const FrameInput& in, gpu::Uploader& uploader,
                        shared::FrameParams&) {
    if (in.size != mSize) {
        mSize = in.size;
        mAccumulation = gpu::Buffer(mCtx, gpu::BufferKind::Storage,
                                    std::uint64_t(mSize.x) * mSize.y * sizeof(glm::vec4),
                                    "reference.accumulation");
        mSamples = 0;
    }
    mRestart = mSamples == 0 || changes.restartsAccumulation();
    if (mRestart) mSamples = 0;
    const std::uint32_t samples = std::max(in.lighting.samplesPerFrame, 1u);
    mSamples += samples;
    shared::ReferenceParams p = referenceParams(in.lighting);
    const std::uint32_t perDispatch = referenceSamplesPerDispatch(in.scene, in.lighting.bounces);
    mDispatches = (samples + perDispatch - 1) / perDispatch;
    while (mParams.size() < mDispatches)
        mParams.emplace_back(mCtx, gpu::BufferKind::Storage, sizeof(shared::ReferenceParams),
                             "reference.params");
    for (std::uint32_t d = 0; d < mDispatches; ++d) {
        p.samples = std::min(perDispatch, samples - d * perDispatch);
        uploader.write(mParams[d], 0, &p, sizeof(p));
    }
}

void Reference::record(FrameCommands& commands, const FrameBuffers& frame) {
    gpu::CommandList& cmd = commands.current();
    if (mRestart) cmd.fillBuffer(mAccumulation, 0);
    std::vector<ReferenceIo> series;
    for (std::uint32_t d = 0; d < mDispatches; ++d)
        series.push_back({frame.frameParams, mParams[d], mAccumulation, frame.radiance});
    mPass.recordSeries(cmd, frame.scene, series, mSize);
}

void Reference::collect(FrameResult& result) { result.referenceSamples = mSamples; }

}  // namespace engine::render
