// Saving and loading the sandbox's worlds. A save is a scene file (palette, camera presets,
// sky; world/scene_file_writer.h) plus a voxel payload beside it that the scene file names in
// a generator, so `vox render SAVE.toml` and `vox play SAVE.toml` both open it.
//
// Saves are atomic as a pair. The payload goes to a new file, `STEM.N.bricks` (N one more
// than any before), written to a temporary name, flushed and renamed; then the scene file is
// replaced the same way, and that rename is the commit. A crash or error at any point leaves
// the previous scene file naming the previous payload, both intact; payloads no scene file
// names are removed by the next successful save.
//
// The payload is io/brick_payload.h for now; the design calls for .vdb, and this interface is
// where the OpenVDB exporter/importer plugs in when it lands.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>

#include "core/error.h"
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
    virtual engine::Status save(const engine::world::Scene& scene, const std::filesystem::path& sceneFile) = 0;
    virtual engine::Result<engine::world::Scene> load(const std::filesystem::path& sceneFile) = 0;
    // True if `sceneFile` is a save this store wrote (and may overwrite); false for hand-written
    // scene files, which a save must never replace.
    virtual bool isSave(const std::filesystem::path& sceneFile) const = 0;
};

std::unique_ptr<WorldStore> makeWorldStore(SaveFaults faults = {});

}  // namespace game
