// A world in a region store (world/region_store.h): its voxels as regions, its scene tables
// (world, material, object, camera, sky, indirect, path) as scene keys, each the scene-file text
// of that table — so the store alone is the whole world (`vox play W.db`), and a scene file can
// name it with a `store` generator (scene/generators/store_keys.cpp) to stay the human-readable
// description beside it.
//
// Saves are incremental: snapshotStore copies only the regions edited since the saver's last
// save (BrickGrid::regionsEditedAfter) — cheap, in the frame — and commitSnapshot encodes and
// commits them in one transaction, on any thread. docs/WORLD_STORE.md has the schema and the
// guarantees.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "world/region_codec.h"
#include "world/region_store.h"
#include "world/scene.h"

namespace engine::scene {

using SceneKeys = std::vector<std::pair<std::string, std::string>>;

// The scene's tables as scene keys, one per top-level table, without the grid's generators (the
// regions are the voxels). Objects keep their own generators.
// `objectGenerators`: written instead of each object's own (a save's model payloads).
SceneKeys sceneKeysOf(
    const world::Scene& scene,
    const std::vector<std::vector<world::GeneratorRecord>>* objectGenerators = nullptr);
// The scene-file text of the keys, in the order the reader wants them.
std::string sceneTextOfKeys(const std::map<std::string, std::string>& keys);

// What a save writes, taken in the frame.
struct StoreSnapshot {
    bool whole = false;  // every region (and no other row survives): a first save, an import
    glm::ivec3 worldSizeInVoxels{0};
    std::vector<world::RegionSnapshot> regions;  // empty ones are erased from the store
    SceneKeys sceneKeys;
};
// The listed regions (a save's dirty ones), or every region with `whole`.
StoreSnapshot snapshotStore(
    const world::Scene& scene, std::span<const world::RegionKey> regions, bool whole,
    const std::vector<std::vector<world::GeneratorRecord>>* objectGenerators = nullptr);

struct StoreWriteReport {
    std::size_t regionsWritten = 0;
    std::size_t regionsErased = 0;
    std::uint64_t rawBytes = 0;     // before compression
    std::uint64_t storedBytes = 0;  // compressed
    double encodeMs = 0.0;
    double commitMs = 0.0;
    std::uint64_t fileBytes = 0;   // the store's size on disk afterwards
    std::uint64_t regionRows = 0;  // the store's regions afterwards (its non-empty ones)
    std::uint64_t commits = 0;     // the store's commit counter afterwards
};

// Encodes the snapshot's regions and commits them with its scene keys in one transaction; makes
// the store if the file does not exist. A failure (full disk, a file that is not a store) leaves
// the store as it was and says so in one line. An incremental snapshot given `expectedCommits`
// is refused if the store's commit counter differs (another writer, or a file made anew): its
// regions would be written over a world they do not belong to.
Result<StoreWriteReport> commitSnapshot(const StoreSnapshot& snapshot,
                                        const std::filesystem::path& store,
                                        std::optional<std::uint64_t> expectedCommits = {});
// The same through a store kept open (vox play's saver): no open, and no close — closing the
// last connection checkpoints the write-ahead log into the file, which cost a one-region save
// more than its encode and commit together (docs/WORLD_STORE.md).
Result<StoreWriteReport> commitSnapshot(const StoreSnapshot& snapshot, world::RegionStore& store,
                                        std::optional<std::uint64_t> expectedCommits = {});

// A whole world as a store at `path` (vox import, convert), region by region — each region is
// copied, encoded and written in turn, so the write holds one region at a time besides the
// world. A new file is written under a temporary name and renamed into place; an existing store
// is replaced in one transaction. regionCells other than the default is for measurements.
Result<StoreWriteReport> writeWorldStore(const world::Scene& scene,
                                         const std::filesystem::path& path,
                                         int regionCells = world::kRegionCells);

// Loads the world a store holds. With `box`, only the regions meeting it are read, into a grid of
// the box rounded out to whole 8^3 cells (a box export); the cameras stay where they were. Without
// `regions`, none is read: the grid is empty and the world's size (a streamed world,
// world/grid_streaming.h).
Result<world::Scene> loadWorldStore(const std::filesystem::path& path,
                                    std::optional<world::Box> box = {}, bool regions = true);

// Reads a store's regions into scene.grid, its material ids mapped by name onto scene.palette
// (materials the palette lacks are added): the `store` generator.
Status readStoreInto(world::Scene& scene, const std::filesystem::path& path);

}  // namespace engine::scene
