#include "game/streamed_world.h"

#include <algorithm>

#include "scene/world_regions.h"

namespace game {

namespace fs = std::filesystem;
namespace world = engine::world;

engine::Result<std::optional<StreamedWorld>> openStreamedWorld(const fs::path& path,
                                                               const StreamOptions& options) {
    if (options.radius == 0.0f) return std::optional<StreamedWorld>{};
    const bool asked = options.radius > 0.0f;
    const std::string ext = path.extension().string();
    if (ext != ".db" && ext != ".toml") {
        if (asked)
            return engine::makeError(
                "--stream-radius: {}: only a store (.db) or a scene file streams", path.string());
        return std::optional<StreamedWorld>{};
    }
    // The world without its voxels: its tables, and its generators read but not run.
    auto lean = engine::scene::loadWorldLean(path);
    if (!lean) return lean.error();
    const glm::ivec3 size = lean->grid.sizeInVoxels();
    if (!asked && std::max(size.x, size.z) <= kStreamByDefaultVoxels)
        return std::optional<StreamedWorld>{};

    auto regions = engine::scene::worldRegionsOf(*lean, path);
    if (!regions) return regions.error();
    if (!regions->source) {
        if (asked)
            return engine::makeError("--stream-radius: {}: cannot stream: {}", path.string(),
                                     regions->whyNot);
        return std::optional<StreamedWorld>{};  // not streamable: loaded whole
    }
    StreamedWorld out;
    out.store = regions->store;
    const world::ResidencySettings settings{
        options.radius > 0.0f ? options.radius : StreamOptions::kDefaultRadius,
        options.budgetMiB << 20};
    out.streaming = std::make_unique<world::GridStreaming>(
        std::move(regions->source), settings, options.regionsPerFrame, options.bricksPerFrame);
    out.scene = std::move(*lean);
    return std::optional<StreamedWorld>(std::move(out));
}

}  // namespace game
