#include "render/renderer.h"

#include <cstring>

#include "gpu/command_list.h"

namespace engine::render {

double FrameResult::totalMs() const {
    double total = 0.0;
    for (const auto& [name, ms] : passMs) total += ms;
    return total;
}

Renderer::Renderer(gpu::Context& ctx)
    : mCtx(ctx), mWorld(ctx), mUploader(ctx), mTimer(ctx, 16), mPrimary(ctx), mShade(ctx), mTonemap(ctx) {
    mFrameParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::FrameParams), "frame.params");
}

void Renderer::resize(std::uint32_t width, std::uint32_t height) {
    if (mSize == glm::uvec2(width, height)) return;
    mSize = {width, height};
    std::uint64_t pixels = std::uint64_t(width) * height;
    mGBuffer = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(shared::GBufferTexel), "frame.gbuffer");
    mRadiance = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::vec4), "frame.radiance");
    mLdr = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(std::uint32_t), "frame.ldr");
    mRayStats = gpu::Buffer(mCtx, gpu::BufferKind::Storage, pixels * sizeof(glm::uvec4), "frame.rayStats");
}

FrameResult Renderer::render(world::Scene& scene, const world::CameraPreset& camera, const FrameSettings& settings) {
    resize(settings.width, settings.height);
    FrameResult result;
    gpu::CommandList cmd(mCtx, &mTimer);
    cmd.begin();
    cmd.beginPass("upload");
    result.upload = mWorld.sync(scene, mUploader);
    scene.grid.clearDirty();
    shared::FrameParams params = makeFrameParams(camera, scene.sky, settings);
    mUploader.write(mFrameParams, 0, &params, sizeof(params));
    mUploader.record(cmd);
    cmd.endPass();

    mPrimary.record(cmd, {mWorld, mFrameParams, mGBuffer}, mSize);
    mShade.record(cmd, {mWorld, mFrameParams, mGBuffer, mRadiance, mRayStats}, mSize);
    mTonemap.record(cmd, {mFrameParams, mRadiance, mLdr}, mSize);
    cmd.submitAndWait();
    result.passMs = mTimer.results();
    return result;
}

FrameImages Renderer::readback() {
    FrameImages images;
    images.width = mSize.x;
    images.height = mSize.y;
    const gpu::Buffer* sources[] = {&mRadiance, &mLdr, &mGBuffer, &mRayStats};
    std::uint64_t total = 0;
    for (const gpu::Buffer* b : sources) total += b->size();
    gpu::Buffer readback(mCtx, gpu::BufferKind::Readback, total, "frame.readback");
    gpu::CommandList cmd(mCtx);
    cmd.begin();
    std::uint64_t offset = 0;
    for (const gpu::Buffer* b : sources) {
        cmd.copyBuffer(*b, readback, {{0, offset, b->size()}});
        offset += b->size();
    }
    cmd.barrier();
    cmd.submitAndWait();

    const auto* bytes = static_cast<const std::uint8_t*>(readback.mapped());
    auto take = [&](auto& vec, const gpu::Buffer& b, std::uint64_t& at) {
        vec.resize(b.size() / sizeof(vec[0]));
        std::memcpy(vec.data(), bytes + at, b.size());
        at += b.size();
    };
    std::uint64_t at = 0;
    take(images.radiance, mRadiance, at);
    take(images.rgba8, mLdr, at);
    take(images.gbuffer, mGBuffer, at);
    take(images.rayStats, mRayStats, at);
    return images;
}

}  // namespace engine::render
