#include "game/world_store.h"

#include <cctype>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "io/vdb_import.h"
#include "io/vox_import.h"
#include "scene/generators/vdb_keys.h"
#include "scene/scene_file.h"
#include "scene/world_pair.h"

namespace game {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSaveMarker = "Saved by vox play";

class VdbWorldStore final : public WorldStore {
public:
    explicit VdbWorldStore(SaveFaults faults) : mFaults(std::move(faults)) {}

    engine::Status save(const engine::world::Scene& scene, const fs::path& sceneFile) override {
        fs::path dir = sceneFile.parent_path();
        std::error_code ec;
        if (!dir.empty()) fs::create_directories(dir, ec);
        if (ec) return engine::makeError("{}: cannot create the folder: {}", dir.string(), ec.message());
        if (fs::is_regular_file(sceneFile, ec) && !isSave(sceneFile))  // a folder: writeWorldPair says so
            return engine::makeError("{}: not a save written by vox play; refusing to overwrite it", sceneFile.string());

        // rule "ids": our own file's material grid, mapped by name onto the palette listed above
        // it, which is the same palette in the same order; so every id comes back unchanged.
        // Everything else (objects with their generators, [indirect], [path]) is written as loaded.
        auto text = [&](const std::string& payloadName) {
            std::vector<engine::world::GeneratorRecord> generators{engine::scene::vdbPayloadGenerator(payloadName, /*ids=*/true)};
            return engine::scene::sceneText(scene, {.headerComment = kSaveMarker, .generators = &generators});
        };
        return engine::scene::writeWorldPair(scene, sceneFile, text, {.beforeCommit = mFaults.beforeCommit});
    }

    engine::Result<engine::world::Scene> load(const fs::path& sceneFile) override {
        // A volume or a MagicaVoxel model stands for itself, imported with the defaults (like
        // vox render X.vdb); Ctrl+S then saves it as a world under saves/.
        if (sceneFile.extension() == ".vdb") return engine::io::importVdb(sceneFile);
        if (sceneFile.extension() == ".vox") return engine::io::importVox(sceneFile);
        return engine::scene::loadSceneFile(sceneFile);
    }

    bool isSave(const fs::path& sceneFile) const override {
        std::ifstream in(sceneFile);
        std::string first;
        std::getline(in, first);
        return first == std::string("# ") + kSaveMarker;
    }

private:
    SaveFaults mFaults;
};

}  // namespace

fs::path defaultSavePath(std::string_view worldName) {
    std::string safe;
    for (char c : worldName) {
        const bool allowed = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' || c == ' ';
        if (safe.size() < 64) safe += allowed ? c : '_';
    }
    while (!safe.empty() && (safe.front() == '.' || safe.front() == ' ')) safe.erase(safe.begin());  // no "..", no hidden file
    if (safe.empty()) safe = "untitled";
    return fs::path("saves") / (safe + ".toml");
}

std::unique_ptr<WorldStore> makeWorldStore(SaveFaults faults) { return std::make_unique<VdbWorldStore>(std::move(faults)); }

}  // namespace game
