// BackgroundSaver: the saves of `vox play` (Ctrl+S, the quit prompt, autosave) off the frame.
// In the frame, request() copies only the regions edited since the last save to the same file
// (BrickGrid::regionsEditedAfter; the whole world the first time a file is written in a session,
// unless the world was loaded from that very store) plus the scene keys; a worker thread encodes
// them and commits them to the store in one transaction (scene/store_world.h), then rewrites the
// scene file that names the store. The frame never waits for the disk; finished saves come back
// through poll(). A failed save leaves the store as it was and marks its regions edited again.
//
// Save paths: `W.toml` saves the store `W.db` beside it and the scene file `W.toml` naming it (a
// `store` generator, headed kSaveMarker); `W.db` saves the store alone.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/error.h"
#include "scene/store_world.h"
#include "scene/world_pair.h"
#include "world/scene.h"

namespace game {

// The store a save path writes: itself for `.db`, else `STEM.db` beside it.
std::filesystem::path storePathFor(const std::filesystem::path& savePath);

// What the HUD says about a store: its regions and size on disk (absent: not written yet).
struct StoreStatus {
    bool exists = false;
    std::uint64_t regions = 0, fileBytes = 0;
};
StoreStatus readStoreStatus(const std::filesystem::path& store);  // opens it read-only
// "store w.db: 2048 regions, 412.3 MiB on disk" or "store w.db: not written yet".
std::string describeStore(const std::filesystem::path& store, const StoreStatus& status);

class BackgroundSaver {
public:
    BackgroundSaver();
    ~BackgroundSaver();  // finishes the queued saves, then stops the worker
    BackgroundSaver(const BackgroundSaver&) = delete;
    BackgroundSaver& operator=(const BackgroundSaver&) = delete;

    // The scene's grid was just read whole from the store `store` (scene/generators/store_keys.h
    // storeOfScene): saves to it can write only what changes from now on.
    void worldLoaded(engine::world::Scene& scene, const std::filesystem::path& store);

    // The grid holds only the resident regions of a streamed world (game/streamed_world.h): a save
    // that would write the whole world (a first save to another store, or after the store changed)
    // is refused — it would erase every region not in memory.
    void setPartialGrid(bool partial) { mPartialGrid = partial; }

    struct Done {
        std::filesystem::path savePath;
        bool autosave = false;
        std::uint64_t worldVersion = 0;  // what the caller passed to request()
        bool whole = false;
        engine::Status status;
        engine::scene::StoreWriteReport report;
        double workerMs = 0.0;  // encode + commit + scene file, on the worker
        double frameMs = 0.0;   // the snapshot request() took in the frame
        bool resync = false;    // the store's history is unknown now: the next save is whole
    };

    // Takes the snapshot now and queues the write; returns the number of regions copied. Refuses
    // (at once) a scene file that is not a save.
    engine::Result<std::size_t> request(engine::world::Scene& scene,
                                        const std::filesystem::path& savePath, bool autosave,
                                        std::uint64_t worldVersion);
    // Saves finished since the last call, in order. The caller re-marks nothing: a failed save's
    // regions are marked edited again here (scene.grid is the one given to request()).
    std::vector<Done> poll(engine::world::Scene& scene);
    // Blocks until every queued save is done (quitting).
    void waitIdle();
    bool busy() const;

private:
    struct Job {
        std::filesystem::path savePath, store;
        bool autosave = false;
        std::uint64_t worldVersion = 0;
        std::optional<std::uint64_t> expectedCommits;
        engine::scene::StoreSnapshot snapshot;
        std::string sceneText;                             // for a .toml save path
        std::vector<engine::scene::PayloadFile> payloads;  // object models beside the save
        std::vector<engine::world::RegionKey> keys;
        double frameMs = 0.0;
    };
    void run();

    // Frame side: per store, the grid's edit epoch at its last snapshot (absent: write whole).
    std::map<std::filesystem::path, std::uint32_t> mSavedEpoch;
    bool mPartialGrid = false;

    mutable std::mutex mMutex;
    std::condition_variable mWake, mIdle;
    std::deque<Job> mQueue;
    std::vector<std::pair<Done, std::vector<engine::world::RegionKey>>> mDone;
    // Per store, its commit counter after our last commit there (or at loading); under mMutex.
    std::map<std::filesystem::path, std::uint64_t> mCommits;
    bool mWorking = false;
    bool mStop = false;
    // Worker only: the stores saved to, kept open — closing the last connection checkpoints the
    // write-ahead log, which cost a one-region save more than its encode and commit. A store
    // whose file was replaced since (another inode) is opened again.
    struct OpenStore {
        engine::world::RegionStore store;
        std::uint64_t device = 0, inode = 0;
    };
    std::map<std::filesystem::path, OpenStore> mOpenStores;
    engine::Result<engine::scene::StoreWriteReport> commit(const Job& job,
                                                           std::optional<std::uint64_t> expected);
    std::thread mWorker;
};

}  // namespace game
