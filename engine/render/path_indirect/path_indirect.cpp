#include "render/path_indirect/path_indirect.h"

#include <algorithm>

namespace engine::render {

PathIndirect::PathIndirect(gpu::Context& ctx) : mCtx(ctx), mPass(ctx) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::PathIndirectParams), "path.params");
}

void PathIndirect::prepare(const lighting::LightingSettings& lighting, glm::uvec2 size, std::uint32_t frameIndex,
                           bool restart, gpu::Uploader& uploader) {
    if (size != mSize) {
        mSize = size;
        mAccumulation = gpu::Buffer(mCtx, gpu::BufferKind::Storage, std::uint64_t(size.x) * size.y * sizeof(glm::vec4),
                                    "path.accumulation");
        restart = true;
    }
    restart = restart || !lighting.path.accumulate || mPaths == 0;
    shared::PathIndirectParams p{};
    p.samples = std::max(lighting.path.samples, 1u);
    p.bounces = std::max(lighting.path.bounces, 1u);
    p.flags = (lighting.brickLights ? shared::PATH_INDIRECT_BRICK_LIGHTS : 0u) | (restart ? shared::PATH_INDIRECT_RESTART : 0u);
    p.frame = frameIndex;
    p.seed = lighting.seed;
    uploader.write(mParams, 0, &p, sizeof(p));
    mPaths = (restart ? 0u : mPaths) + p.samples;
}

void PathIndirect::record(gpu::CommandList& cmd, const SceneBindings& scene, const Io& io) {
    mPass.record(cmd, scene, {io.frameParams, mParams, io.gbuffer, mAccumulation, io.indirect, io.radiance}, mSize);
}

}  // namespace engine::render
