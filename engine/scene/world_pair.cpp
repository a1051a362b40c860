#include "scene/world_pair.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <utility>

#include "core/atomic_file.h"
#include "io/vdb_export.h"

namespace engine::scene {

namespace fs = std::filesystem;

namespace {

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

}  // namespace

Status writeWorldPair(const world::Scene& scene, const fs::path& sceneFile,
                      const std::function<std::string(const std::string& payloadFileName)>& sceneText,
                      const WorldPairOptions& options) {
    // The scene file's temporary first: a scene path that is a folder (or in no folder) is
    // refused before any payload is written.
    AtomicFile sceneOut;
    if (Status s = sceneOut.open(sceneFile); !s) return s;

    const fs::path dir = sceneFile.parent_path();
    removeStaleTemporaries(dir);  // left by saves killed mid-write (every save, not once per process)
    const std::string stem = sceneFile.stem().string();
    std::uint64_t generation = 1;
    for (const auto& [n, path] : payloads(dir, stem)) generation = std::max(generation, n + 1);
    const fs::path payload = dir / fmt::format("{}.{}.vdb", stem, generation);
    // Colour grids included so other OpenVDB tools show the world in colour (loading needs only
    // the ids).
    if (Status s = io::exportVdb(scene, payload); !s) return s;

    Status s = sceneOut.write(sceneText(payload.filename().string()));
    if (s && options.beforeCommit) s = options.beforeCommit();
    if (s) s = sceneOut.commit();
    std::error_code ec;
    if (!s) {
        sceneOut.abandon();
        fs::remove(payload, ec);  // the old scene file still names the old payload
        return s;
    }
    for (const auto& [n, path] : payloads(dir, stem)) {
        const bool kept = std::any_of(options.keep.begin(), options.keep.end(),
                                      [&](const fs::path& k) { return fs::equivalent(k, path, ec); });
        if (n != generation && !kept) fs::remove(path, ec);
    }
    return {};
}

}  // namespace engine::scene
