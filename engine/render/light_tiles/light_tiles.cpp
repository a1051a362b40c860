#include "render/light_tiles/light_tiles.h"

#include <utility>

#include "gpu/command_list.h"
#include "gpu/uploader.h"
#include "render/frame_commands.h"
#include "shared/light_tiles.h"
#include "shared/shader_features.h"

namespace engine::render {

namespace {
constexpr std::uint64_t kSampleBytes = std::uint64_t(shared::LIGHT_TILE_COUNT) *
                                       shared::LIGHT_TILE_SIZE * sizeof(shared::LightTileSample);
}  // namespace

LightTiles::LightTiles(gpu::Context& ctx)
    : mCtx(ctx), mPass(ctx, "light_tiles", "light_tiles/presample", 2) {}

std::uint64_t LightTiles::deviceBytes() { return sizeof(shared::LightTilesParams) + kSampleBytes; }

TechniquePlan LightTiles::plan(const lighting::LightingSettings& l, const SceneShape&, glm::uvec2) {
    TechniquePlan p;
    p.runs = lighting::usesLightTiles(l);
    p.deviceBytes = deviceBytes();
    p.features = {{FEATURE_LIGHT_TILES, 1u}};
    return p;
}

void LightTiles::prepare(const FrameChanges&, const FrameInput& in, gpu::Uploader& uploader,
                         shared::FrameParams& params) {
    if (!mSamples.valid()) {  // first use
        mParams = gpu::Buffer(mCtx, gpu::BufferKind::Storage, sizeof(shared::LightTilesParams),
                              "light_tiles.params");
        mSamples = gpu::Buffer(mCtx, gpu::BufferKind::Storage, kSampleBytes, "light_tiles.samples");
    }
    const shared::LightTilesParams p{in.frameIndex, in.lighting.seed, 0u, 0u};
    uploader.write(mParams, 0, &p, sizeof(p));
    const std::uint64_t address = mSamples.deviceAddress();
    params.lightTiles = glm::uvec4(std::uint32_t(address), std::uint32_t(address >> 32), 0u, 0u);
}

void LightTiles::record(FrameCommands& commands, const FrameBuffers& frame) {
    const PassBinding own[] = {{shared::LIGHT_TILES_BINDING_PARAMS, &std::as_const(mParams)},
                               {shared::LIGHT_TILES_BINDING_SAMPLES, &mSamples}};
    const std::uint32_t entries = shared::LIGHT_TILE_COUNT * shared::LIGHT_TILE_SIZE;
    gpu::CommandList& cmd = commands.current();
    mPass.record(cmd, frame.scene, own, glm::uvec2(entries / shared::LIGHT_TILES_GROUP_SIZE, 1u));
    // The candidates and the cache read the tiles by address, which declares no binding: wait here.
    cmd.barrier();
}

}  // namespace engine::render
