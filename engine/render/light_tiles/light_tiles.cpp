#include "render/light_tiles/light_tiles.h"

#include "gpu/uploader.h"
#include "shared/light_tiles.h"

namespace engine::render {

bool lightTilesUsed(const lighting::LightingSettings& l) {
    using lighting::Method;
    const bool candidates = l.method == Method::Restir || l.method == Method::Ris;
    const bool cache = l.indirect == lighting::Indirect::Cache && l.method != Method::Reference;
    return l.byPower && l.restir.lightTiles && (candidates || cache);
}

LightTiles::LightTiles(gpu::Context& ctx) : mPass(ctx, "light_tiles", "light_tiles/presample", 2) {
    mParams = gpu::Buffer(ctx, gpu::BufferKind::Storage, sizeof(shared::LightTilesParams), "light_tiles.params");
    mSamples = gpu::Buffer(ctx, gpu::BufferKind::Storage,
                           std::uint64_t(shared::LIGHT_TILE_COUNT) * shared::LIGHT_TILE_SIZE * sizeof(shared::LightTileSample),
                           "light_tiles.samples");
}

void LightTiles::writeParams(gpu::Uploader& uploader, std::uint32_t frameIndex, std::uint32_t seed) {
    const shared::LightTilesParams p{frameIndex, seed, 0u, 0u};
    uploader.write(mParams, 0, &p, sizeof(p));
}

void LightTiles::record(gpu::CommandList& cmd, const SceneBindings& scene) {
    const PassBinding own[] = {{shared::LIGHT_TILES_BINDING_PARAMS, &mParams}, {shared::LIGHT_TILES_BINDING_SAMPLES, &mSamples}};
    const std::uint32_t entries = shared::LIGHT_TILE_COUNT * shared::LIGHT_TILE_SIZE;
    mPass.record(cmd, scene, own, glm::uvec2(entries / shared::LIGHT_TILES_GROUP_SIZE, 1u));
}

glm::uvec4 LightTiles::frameField() const {
    const std::uint64_t address = mSamples.deviceAddress();
    return glm::uvec4(std::uint32_t(address), std::uint32_t(address >> 32), 0u, 0u);
}

}  // namespace engine::render
