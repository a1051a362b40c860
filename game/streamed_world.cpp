#include "game/streamed_world.h"

#include <algorithm>
#include <any>

#include "scene/generators/store_keys.h"
#include "scene/scene_file.h"
#include "scene/store_world.h"
#include "world/generators.h"
#include "world/store_region_source.h"
#include "world/terrain_region_source.h"

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
    auto lean = ext == ".db" ? engine::scene::loadWorldStore(path, {}, /*regions=*/false)
                             : engine::scene::loadSceneFile(path, {.gridGenerators = false});
    if (!lean) return lean.error();
    const glm::ivec3 size = lean->grid.sizeInVoxels();
    if (!asked && std::max(size.x, size.z) <= kStreamByDefaultVoxels)
        return std::optional<StreamedWorld>{};

    StreamedWorld out;
    std::unique_ptr<world::RegionSource> source;
    if (fs::path store = engine::scene::storeOfScene(*lean); !store.empty()) {
        // Streamed rows keep the store's material ids: the scene's palette must be the store's.
        if (ext != ".db") {
            auto own = engine::scene::loadWorldStore(store, {}, /*regions=*/false);
            if (!own) return own.error();
            if (own->palette.size() != lean->palette.size())
                return engine::makeError(
                    "{}: cannot stream: its palette differs from its store's ({}); play the store "
                    "itself or --stream-radius 0",
                    path.string(), store.string());
            for (std::size_t i = 1; i < own->palette.size(); ++i)
                if (own->palette[world::MaterialId(i)].name !=
                    lean->palette[world::MaterialId(i)].name)
                    return engine::makeError(
                        "{}: cannot stream: its palette differs from its store's ({}); play the "
                        "store itself or --stream-radius 0",
                        path.string(), store.string());
        }
        auto opened = world::StoreRegionSource::open(store, lean->palette.size());
        if (!opened) return opened.error();
        if (opened->worldSizeInCells() != lean->grid.sizeInCells())
            return engine::makeError("{}: cannot stream: its size differs from its store's ({})",
                                     path.string(), store.string());
        source = std::make_unique<world::StoreRegionSource>(std::move(*opened));
        out.store = store;
    } else if (lean->generators.size() == 1 && lean->generators[0].type == "terrain") {
        source = std::make_unique<world::TerrainRegionSource>(
            size, std::any_cast<const world::TerrainParams&>(lean->generators[0].params));
    } else {
        if (asked)
            return engine::makeError(
                "--stream-radius: {}: cannot stream: only a store or a world of one terrain "
                "generator streams ({} generator(s) here)",
                path.string(), lean->generators.size());
        // Not streamable: loaded whole (its generators were not run).
        return std::optional<StreamedWorld>{};
    }
    const world::ResidencySettings settings{
        options.radius > 0.0f ? options.radius : StreamOptions::kDefaultRadius,
        options.budgetMiB << 20};
    out.streaming = std::make_unique<world::GridStreaming>(std::move(source), settings,
                                                           options.regionsPerFrame);
    out.scene = std::move(*lean);
    return std::optional<StreamedWorld>(std::move(out));
}

}  // namespace game
