// Saving and loading the sandbox's worlds. A save is a scene file (palette, dynamic objects,
// camera presets, sky, [indirect], [path]; scene/scene_file.h) plus the world's voxels as an
// OpenVDB file beside it
// (io/vdb_export.h, layout in docs/VDB.md) that the scene file names in a `vdb` generator with
// rule "ids", so `vox render SAVE.toml` and `vox play SAVE.toml` both open it and other tools
// read the .vdb directly. Loading a save gives back the saved world voxel for voxel (cell
// encodings included: the exporter writes homogeneous cells as tiles and bricks as leaves) and
// palette for palette (the scene file lists it in order; the import merges the .vdb's by name).
//
// Saves are atomic as a pair (scene/world_pair.h): a crash or error at any point leaves the
// previous scene file naming the previous payload, both intact.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string_view>

#include "core/error.h"
#include "scene/world_pair.h"
#include "world/scene.h"

namespace game {

// Fault injection for tests: runs after the new scene file is fully written to its temporary
// name, before the rename that commits it. An error aborts the save (a real crash there is
// simulated by a hook that exits the process).
struct SaveFaults {
    std::function<engine::Status()> beforeCommit;
};

class WorldStore {
public:
    virtual ~WorldStore() = default;
    virtual engine::Status save(const engine::world::Scene& scene,
                                const std::filesystem::path& sceneFile) = 0;
    // A scene file, a world store (.db), or a .vdb / .vox standing for itself.
    virtual engine::Result<engine::world::Scene> load(const std::filesystem::path& sceneFile) = 0;
    // True if `sceneFile` is a save this store wrote (and may overwrite); false for hand-written
    // scene files, which a save must never replace.
    virtual bool isSave(const std::filesystem::path& sceneFile) const = 0;
};

std::unique_ptr<WorldStore> makeWorldStore(SaveFaults faults = {});

// The dynamic objects' models as payloads beside a save (`STEM.object-HASH.vdb`, rule "ids"), and
// the generators naming them, one list per object in scene order (SceneWriteOptions).
struct ObjectPayloads {
    std::vector<engine::scene::PayloadFile> files;
    std::vector<std::vector<engine::world::GeneratorRecord>> generators;
};
ObjectPayloads objectPayloads(const engine::world::Scene& scene,
                              const std::filesystem::path& sceneFile);

// Where a world saves by default: saves/NAME.toml, NAME from the scene file's `name` by
// game/world_file_stem.h, so a hostile name like "../../x" or "/etc/x" cannot save outside
// saves/, and different names never share a save.
std::filesystem::path defaultSavePath(std::string_view worldName);

}  // namespace game
