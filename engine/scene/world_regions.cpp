#include "scene/world_regions.h"

#include <any>

#include "scene/generators/store_keys.h"
#include "scene/scene_file.h"
#include "scene/store_world.h"
#include "world/generators.h"
#include "world/store_region_source.h"
#include "world/terrain_region_source.h"

namespace engine::scene {

namespace fs = std::filesystem;

Result<world::Scene> loadWorldLean(const fs::path& path) {
    if (path.extension() == ".db") return loadWorldStore(path, {}, /*regions=*/false);
    return loadSceneFile(path, {.gridGenerators = false});
}

namespace {

// Rows keep the store's material ids: a scene file naming the store must have its palette.
Status checkSamePalette(const world::Scene& lean, const fs::path& path, const fs::path& store) {
    auto own = loadWorldStore(store, {}, /*regions=*/false);
    if (!own) return own.error();
    bool same = own->palette.size() == lean.palette.size();
    for (std::size_t i = 1; same && i < own->palette.size(); ++i)
        same = own->palette[world::MaterialId(i)].name == lean.palette[world::MaterialId(i)].name;
    if (!same)
        return makeError(
            "{}: cannot read its regions: its palette differs from its store's ({}); use the "
            "store itself",
            path.string(), store.string());
    return {};
}

}  // namespace

Result<WorldRegions> worldRegionsOf(const world::Scene& lean, const fs::path& path) {
    WorldRegions out;
    if (fs::path store = storeOfScene(lean); !store.empty()) {
        if (path.extension() != ".db")
            if (Status s = checkSamePalette(lean, path, store); !s) return s.error();
        auto opened = world::StoreRegionSource::open(store, lean.palette.size());
        if (!opened) return opened.error();
        if (opened->worldSizeInCells() != lean.grid.sizeInCells())
            return makeError("{}: cannot read its regions: its size differs from its store's ({})",
                             path.string(), store.string());
        out.source = std::make_unique<world::StoreRegionSource>(std::move(*opened));
        out.store = store;
    } else if (lean.generators.size() == 1 && lean.generators[0].type == "terrain") {
        out.source = std::make_unique<world::TerrainRegionSource>(
            lean.grid.sizeInVoxels(),
            std::any_cast<const world::TerrainParams&>(lean.generators[0].params));
    } else {
        std::string made;
        for (const world::GeneratorRecord& g : lean.generators)
            made += (made.empty() ? "" : ", ") + g.type;
        out.whyNot =
            "only a store or a world made by one terrain generator is read region by region (made "
            "by: " +
            (made.empty() ? std::string("nothing") : made) + ")";
    }
    return out;
}

}  // namespace engine::scene
