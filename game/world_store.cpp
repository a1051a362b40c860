#include "game/world_store.h"

#include <fmt/format.h>
#include <string>

#include "game/world_file_stem.h"
#include "io/vdb_export.h"
#include "io/vdb_import.h"
#include "io/vox_import.h"
#include "scene/generators/vdb_keys.h"
#include "scene/scene_file.h"
#include "scene/store_world.h"
#include "scene/world_pair.h"
#include "world/region_store.h"

namespace game {

namespace fs = std::filesystem;

namespace {

// A model's name for its payload: FNV-1a over its size, voxel ids and their material names, so
// an unchanged model keeps its file from save to save.
std::uint64_t modelHash(const engine::world::DynamicObject& o,
                        const engine::world::Palette& palette) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](std::uint64_t v) {
        for (int b = 0; b < 8; ++b) h = (h ^ ((v >> (8 * b)) & 0xff)) * 1099511628211ull;
    };
    mix(std::uint64_t(o.modelSize.x) | std::uint64_t(o.modelSize.y) << 21 |
        std::uint64_t(o.modelSize.z) << 42);
    std::vector<bool> used(palette.size(), false);
    for (int z = 0; z < o.modelSize.z; ++z)
        for (int y = 0; y < o.modelSize.y; ++y)
            for (int x = 0; x < o.modelSize.x; ++x) {
                const engine::world::MaterialId m = o.model->get({x, y, z});
                mix(m);
                if (m < used.size()) used[m] = true;
            }
    for (std::size_t m = 0; m < used.size(); ++m) {
        if (!used[m]) continue;
        for (char c : palette[engine::world::MaterialId(m)].name) mix(std::uint8_t(c));
    }
    return h;
}

class VdbWorldStore final : public WorldStore {
public:
    explicit VdbWorldStore(SaveFaults faults) : mFaults(std::move(faults)) {}

    engine::Status save(const engine::world::Scene& scene, const fs::path& sceneFile) override {
        fs::path dir = sceneFile.parent_path();
        std::error_code ec;
        if (!dir.empty()) fs::create_directories(dir, ec);
        if (ec)
            return engine::makeError("{}: cannot create the folder: {}", dir.string(),
                                     ec.message());
        if (fs::is_regular_file(sceneFile, ec) &&
            !isSave(sceneFile))  // a folder: writeWorldPair says so
            return engine::makeError("{}: not a save written by vox play; refusing to overwrite it",
                                     sceneFile.string());

        // rule "ids": our own file's material grid, mapped by name onto the palette listed above
        // it, which is the same palette in the same order; so every id comes back unchanged.
        // Everything else (objects with their generators, [indirect], [path]) is written as loaded.
        ObjectPayloads objects = objectPayloads(scene, sceneFile);
        std::vector<std::vector<engine::world::GeneratorRecord>>& objectGenerators =
            objects.generators;
        engine::scene::WorldPairOptions options{.beforeCommit = mFaults.beforeCommit};
        options.extraPayloads = std::move(objects.files);
        auto text = [&](const std::string& payloadName) {
            std::vector<engine::world::GeneratorRecord> generators{
                engine::scene::vdbPayloadGenerator(payloadName, /*ids=*/true)};
            return engine::scene::sceneText(scene, {.headerComment = engine::scene::kSaveMarker,
                                                    .generators = &generators,
                                                    .objectGenerators = &objectGenerators});
        };
        return engine::scene::writeWorldPair(scene, sceneFile, text, options);
    }

    engine::Result<engine::world::Scene> load(const fs::path& sceneFile) override {
        // A volume or a MagicaVoxel model stands for itself, imported with the defaults (like
        // vox render X.vdb); Ctrl+S then saves it as a world under saves/.
        if (sceneFile.extension() == ".vdb") return engine::io::importVdb(sceneFile);
        if (sceneFile.extension() == ".vox") return engine::io::importVox(sceneFile);
        if (sceneFile.extension() == ".db") return engine::scene::loadWorldStore(sceneFile);
        return engine::scene::loadSceneFile(sceneFile);
    }

    bool isSave(const fs::path& sceneFile) const override {
        if (sceneFile.extension() == ".db") return engine::world::RegionStore::isStore(sceneFile);
        return engine::scene::sceneFileMarked(sceneFile, engine::scene::kSaveMarker);
    }

private:
    SaveFaults mFaults;
};

}  // namespace

ObjectPayloads objectPayloads(const engine::world::Scene& scene, const fs::path& sceneFile) {
    // Each object's model goes to a payload of its own, STEM.object-HASH.vdb (same layout, rule
    // "ids"); named by content, an unchanged model is not rewritten. The writers hold what they
    // need by value (the model is shared, never copied), so they may run on another thread.
    ObjectPayloads out;
    const std::string stem = engine::scene::payloadStem(sceneFile);
    for (const engine::world::DynamicObject& o : scene.objects) {
        const std::string name =
            fmt::format("{}.object-{:016x}.vdb", stem, modelHash(o, scene.palette));
        auto write = [model = o.model, objectName = o.name, voxelSize = scene.voxelSize,
                      palette = scene.palette](const fs::path& file) {
            engine::world::Scene m;
            m.name = objectName;
            m.voxelSize = voxelSize;
            m.palette = palette;
            m.grid = *model;
            return engine::io::exportVdb(m, file);
        };
        out.files.push_back({name, write});
        out.generators.push_back({engine::scene::vdbPayloadGenerator(name, /*ids=*/true)});
    }
    return out;
}

fs::path defaultSavePath(std::string_view worldName) {
    return fs::path("saves") / (worldFileStem(worldName) + ".toml");
}

std::unique_ptr<WorldStore> makeWorldStore(SaveFaults faults) {
    return std::make_unique<VdbWorldStore>(std::move(faults));
}

}  // namespace game
