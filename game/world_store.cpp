#include "game/world_store.h"

#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "io/image_io.h"
#include "io/vdb_export.h"
#include "scene/generators/vdb_keys.h"
#include "scene/scene_file.h"

namespace game {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSaveMarker = "Saved by vox play";

// Payload generations of `stem` in `dir`: STEM.N.vdb.
std::vector<std::pair<std::uint64_t, fs::path>> payloads(const fs::path& dir, const std::string& stem) {
    std::vector<std::pair<std::uint64_t, fs::path>> out;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir.empty() ? "." : dir, ec)) {
        std::string name = e.path().filename().string();
        if (name.size() <= stem.size() + 1 || name.compare(0, stem.size() + 1, stem + ".") != 0) continue;
        std::string rest = name.substr(stem.size() + 1);
        auto dot = rest.find('.');
        if (dot == std::string::npos || dot == 0 || rest.substr(dot) != ".vdb") continue;
        std::string digits = rest.substr(0, dot);
        if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 18) continue;
        out.emplace_back(std::stoull(digits), e.path());
    }
    return out;
}

void syncDirectory(const fs::path& dir) {
    int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

class VdbWorldStore final : public WorldStore {
public:
    explicit VdbWorldStore(SaveFaults faults) : mFaults(std::move(faults)) {}

    engine::Status save(const engine::world::Scene& scene, const fs::path& sceneFile) override {
        fs::path dir = sceneFile.parent_path();
        std::error_code ec;
        if (!dir.empty()) fs::create_directories(dir, ec);
        if (ec) return engine::makeError("{}: cannot create the folder: {}", dir.string(), ec.message());
        if (fs::exists(sceneFile, ec) && !isSave(sceneFile))
            return engine::makeError("{}: not a save written by vox play; refusing to overwrite it", sceneFile.string());

        std::string stem = sceneFile.stem().string();
        std::uint64_t generation = 1;
        for (const auto& [n, path] : payloads(dir, stem)) generation = std::max(generation, n + 1);
        fs::path payload = dir / fmt::format("{}.{}.vdb", stem, generation);
        // Atomic on its own (temporary file, flush, rename); colour grids included so other
        // OpenVDB tools show the world in colour (loading needs only the ids).
        engine::Status s = engine::io::exportVdb(scene, payload);
        if (!s) return s;

        // rule "ids": our own file's material grid, mapped by name onto the palette listed above
        // it, which is the same palette in the same order; so every id comes back unchanged.
        // Everything else (objects with their generators, [indirect], [path]) is written as loaded.
        std::vector<engine::world::GeneratorRecord> generators{
            engine::scene::vdbPayloadGenerator(payload.filename().string(), /*ids=*/true)};
        std::string text = engine::scene::sceneText(scene, {.headerComment = kSaveMarker, .generators = &generators});
        s = engine::io::writeAtomically(sceneFile, [&](const fs::path& temp) -> engine::Status {
            {
                std::ofstream out(temp, std::ios::binary);
                out << text;
                out.flush();
                if (!out) return engine::makeError("{}: write failed (disk full?)", sceneFile.string());
            }
            if (mFaults.beforeCommit) return mFaults.beforeCommit();
            return {};
        });
        if (!s) {
            fs::remove(payload, ec);  // the old scene file still names the old payload
            return s;
        }
        syncDirectory(dir);
        for (const auto& [n, path] : payloads(dir, stem)) {
            if (n != generation) fs::remove(path, ec);
        }
        return {};
    }

    engine::Result<engine::world::Scene> load(const fs::path& sceneFile) override {
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
