// RegionStore: a world on disk as one SQLite database (WAL mode), the engine's native world
// format. Schema (docs/WORLD_STORE.md):
//   meta(key TEXT PRIMARY KEY, value TEXT)     format, world size, region size, commit counter
//   scene(key TEXT PRIMARY KEY, toml TEXT)     the scene's tables as scene-file text, one row per
//                                              table (world, material, object, camera, sky, ...)
//   regions(x, y, z INTEGER, raw_bytes INTEGER, data BLOB, PRIMARY KEY (x, y, z)) WITHOUT ROWID
//                                              one row per non-empty region (world/region_codec.h)
// The store holds blobs and text; it does not parse either (world/region_codec.h decodes the
// regions, scene/store_world.h the scene keys).
//
// Guarantees: commit() is one SQLite transaction — every region and key of it, or none, even if
// the process is killed or the disk fills; regions are read by key, so a loader can page one in
// without reading the others. A file that is not a store, or a damaged one, gives one error line.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/error.h"
#include "world/region.h"
#include "world/region_codec.h"

struct sqlite3;

namespace engine::world {

struct RegionStoreInfo {
    glm::ivec3 worldSizeInVoxels{0};
    int regionCells = kRegionCells;
    std::uint64_t commits = 0;  // transactions committed since the store was made
};

struct RegionRow {
    RegionKey key;
    std::uint64_t rawBytes = 0;
    std::uint64_t storedBytes = 0;
};

// One transaction's worth of changes.
struct StoreCommit {
    bool replaceAll = false;  // delete every region and scene key first (a whole-world write)
    std::vector<EncodedRegion> put;
    std::vector<RegionKey> erase;                                // regions now empty
    std::vector<std::pair<std::string, std::string>> sceneKeys;  // replaces the keys given
    std::optional<glm::ivec3> worldSizeInVoxels;                 // a new world size
    // Refused, writing nothing, unless the store's commit counter is this (checked inside the
    // transaction): an incremental save over a store someone else has written since.
    std::optional<std::uint64_t> expectedCommits;
};

class RegionStore {
public:
    // Opens an existing store; `writable` for saves. Refuses a file that is not a store.
    static Result<RegionStore> open(const std::filesystem::path& path, bool writable);
    // Opens the store at `path` for writing, making it (schema, meta) if the file does not exist
    // or is empty; an existing file that is not a store is refused, never overwritten.
    static Result<RegionStore> openOrCreate(const std::filesystem::path& path,
                                            glm::ivec3 worldSizeInVoxels,
                                            int regionCells = kRegionCells);
    // True if the file exists and is a region store (its SQLite application id).
    static bool isStore(const std::filesystem::path& path);

    RegionStore(RegionStore&& other) noexcept;
    RegionStore& operator=(RegionStore&& other) noexcept;
    RegionStore(const RegionStore&) = delete;
    RegionStore& operator=(const RegionStore&) = delete;
    ~RegionStore();

    const RegionStoreInfo& info() const { return mInfo; }
    const std::filesystem::path& path() const { return mPath; }

    // One region's blob, or nullopt when the store has no row (the region is empty).
    Result<std::optional<std::vector<std::uint8_t>>> readRegion(RegionKey key) const;
    // Every region in key order, one at a time (a whole-world load or export streams through it).
    Status forEachRegion(
        const std::function<Status(RegionKey, std::span<const std::uint8_t>)>& visit) const;
    Result<std::vector<RegionRow>> listRegions() const;
    Result<std::uint64_t> regionRows() const;  // how many regions the store holds
    Result<std::map<std::string, std::string>> sceneKeys() const;

    // One transaction: every change in it, or none.
    Status commit(const StoreCommit& change);
    // The same, one change at a time, for writes too large to hold at once (an import streams its
    // regions in): begin, then put/erase/putSceneKey, then commitTransaction. Any failure rolls the
    // transaction back and returns the error; the destructor rolls back an unfinished one.
    // replaceAll: delete every region and scene key first, and take `regionCells` as the size.
    Status begin(bool replaceAll, int regionCells = kRegionCells);
    Status put(const EncodedRegion& region);
    Status erase(RegionKey key);
    Status putSceneKey(const std::string& name, const std::string& toml);
    Status commitTransaction(std::optional<glm::ivec3> worldSizeInVoxels = {});

    // `PRAGMA integrity_check`: empty when it says "ok", else its first complaint.
    Result<std::string> integrityCheck() const;
    // Bytes on disk: the database and its write-ahead log.
    std::uint64_t fileBytes() const;
    // For a connection whose file was unlinked or replaced under it: closing it must not
    // checkpoint, nor delete the write-ahead log by name (the new file's log has that name).
    void abandon();

private:
    RegionStore() = default;
    Status readMeta();
    Error fail(const char* what) const;
    Status failTransaction(const char* what);

    sqlite3* mDb = nullptr;
    std::filesystem::path mPath;
    RegionStoreInfo mInfo;
    bool mInTransaction = false;
    int mPendingRegionCells = 0;  // a replaceAll's region size, taken at commit
};

}  // namespace engine::world
