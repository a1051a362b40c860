#include "game/background_saver.h"

#include <chrono>
#include <fmt/format.h>
#include <sys/stat.h>

#include "core/atomic_file.h"
#include "game/world_store.h"
#include "scene/generators/store_keys.h"
#include "scene/scene_file.h"
#include "scene/world_pair.h"
#include "world/region_store.h"

namespace game {

namespace fs = std::filesystem;

fs::path storePathFor(const fs::path& savePath) {
    if (savePath.extension() == ".db") return savePath;
    fs::path p = savePath;
    p.replace_extension(".db");
    return p;
}

StoreStatus readStoreStatus(const fs::path& store) {
    StoreStatus status;
    if (!engine::world::RegionStore::isStore(store)) return status;
    auto s = engine::world::RegionStore::open(store, /*writable=*/false);
    if (!s) return status;
    auto rows = s->regionRows();
    status.exists = true;
    status.regions = rows ? *rows : 0;
    status.fileBytes = s->fileBytes();
    return status;
}

std::string describeStore(const fs::path& store, const StoreStatus& status) {
    if (!status.exists) return fmt::format("store {}: not written yet", store.filename().string());
    return fmt::format("store {}: {} region(s), {:.1f} MiB on disk", store.filename().string(),
                       status.regions, double(status.fileBytes) / (1 << 20));
}

BackgroundSaver::BackgroundSaver() : mWorker([this] { run(); }) {}

BackgroundSaver::~BackgroundSaver() {
    {
        std::lock_guard lock(mMutex);
        mStop = true;
    }
    mWake.notify_all();
    mWorker.join();
}

void BackgroundSaver::worldLoaded(engine::world::Scene& scene, const fs::path& store) {
    auto opened = engine::world::RegionStore::open(store, /*writable=*/false);
    if (!opened) return;  // then the first save writes the whole world
    std::lock_guard lock(mMutex);
    mCommits[fs::absolute(store)] = opened->info().commits;
    mSavedEpoch[fs::absolute(store)] = scene.grid.closeEditEpoch();
}

engine::Result<std::size_t> BackgroundSaver::request(engine::world::Scene& scene,
                                                     const fs::path& savePath, bool autosave,
                                                     std::uint64_t worldVersion) {
    std::error_code ec;
    if (savePath.extension() != ".db" && fs::is_regular_file(savePath, ec) &&
        !engine::scene::sceneFileMarked(savePath, engine::scene::kSaveMarker))
        return engine::makeError("{}: not a save written by vox play; refusing to overwrite it",
                                 savePath.string());
    const auto start = std::chrono::steady_clock::now();
    Job job;
    job.savePath = savePath;
    job.store = fs::absolute(storePathFor(savePath));
    job.autosave = autosave;
    job.worldVersion = worldVersion;
    auto it = mSavedEpoch.find(job.store);
    const bool whole = it == mSavedEpoch.end();
    if (whole && mPartialGrid)
        return engine::makeError(
            "{}: a streamed world saves only the regions edited since it opened, into the store it "
            "streams from as it was then; not saved",
            job.store.string());
    if (!whole) job.keys = scene.grid.regionsEditedAfter(it->second);
    ObjectPayloads objects = objectPayloads(scene, savePath);
    job.payloads = std::move(objects.files);
    job.snapshot = engine::scene::snapshotStore(scene, job.keys, whole, &objects.generators);
    mSavedEpoch[job.store] = scene.grid.closeEditEpoch();
    if (savePath.extension() != ".db") {
        const std::vector<engine::world::GeneratorRecord> generators{
            engine::scene::storeGenerator(job.store.filename().string())};
        job.sceneText =
            engine::scene::sceneText(scene, {.headerComment = engine::scene::kSaveMarker,
                                             .generators = &generators,
                                             .objectGenerators = &objects.generators});
    }
    const std::size_t regions = job.snapshot.regions.size();
    job.frameMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    {
        std::lock_guard lock(mMutex);
        mQueue.push_back(std::move(job));
    }
    mWake.notify_one();
    return regions;
}

std::vector<BackgroundSaver::Done> BackgroundSaver::poll(engine::world::Scene& scene) {
    std::vector<std::pair<Done, std::vector<engine::world::RegionKey>>> done;
    {
        std::lock_guard lock(mMutex);
        done.swap(mDone);
    }
    std::vector<Done> out;
    for (auto& [d, keys] : done) {
        if (!d.status) {
            if (d.whole || d.resync)
                mSavedEpoch.erase(fs::absolute(storePathFor(d.savePath)));
            else
                scene.grid.markRegionsEdited(keys);
        }
        out.push_back(std::move(d));
    }
    return out;
}

void BackgroundSaver::waitIdle() {
    std::unique_lock lock(mMutex);
    mIdle.wait(lock, [&] { return mQueue.empty() && !mWorking; });
}

bool BackgroundSaver::busy() const {
    std::lock_guard lock(mMutex);
    return !mQueue.empty() || mWorking;
}

namespace {
std::optional<std::pair<std::uint64_t, std::uint64_t>> fileIdentity(const fs::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return std::nullopt;
    return std::pair{std::uint64_t(st.st_dev), std::uint64_t(st.st_ino)};
}
}  // namespace

engine::Result<engine::scene::StoreWriteReport> BackgroundSaver::commit(
    const Job& job, std::optional<std::uint64_t> expected) {
    auto it = mOpenStores.find(job.store);
    if (it != mOpenStores.end() &&
        fileIdentity(job.store) != std::pair{it->second.device, it->second.inode}) {
        it->second.store.abandon();
        mOpenStores.erase(it);
        it = mOpenStores.end();
    }
    if (it == mOpenStores.end()) {
        auto opened =
            engine::world::RegionStore::openOrCreate(job.store, job.snapshot.worldSizeInVoxels);
        if (!opened) return opened.error();
        const auto id = fileIdentity(job.store);
        if (!id) return engine::makeError("{}: cannot stat the store", job.store.string());
        it = mOpenStores.emplace(job.store, OpenStore{std::move(*opened), id->first, id->second})
                 .first;
    }
    auto report = engine::scene::commitSnapshot(job.snapshot, it->second.store, expected);
    if (!report) mOpenStores.erase(it);  // opened afresh next time
    return report;
}

void BackgroundSaver::run() {
    std::unique_lock lock(mMutex);
    for (;;) {
        mWake.wait(lock, [&] { return mStop || !mQueue.empty(); });
        if (mQueue.empty()) return;  // stopping, and nothing left to write
        Job job = std::move(mQueue.front());
        mQueue.pop_front();
        mWorking = true;
        std::optional<std::uint64_t> expected;
        if (auto it = mCommits.find(job.store); it != mCommits.end()) expected = it->second;
        lock.unlock();

        const auto start = std::chrono::steady_clock::now();
        Done d;
        d.savePath = job.savePath;
        d.autosave = job.autosave;
        d.worldVersion = job.worldVersion;
        d.whole = job.snapshot.whole;
        d.frameMs = job.frameMs;
        std::error_code ec;
        if (job.store.has_parent_path()) fs::create_directories(job.store.parent_path(), ec);
        if (!d.whole && !expected) {
            d.status = engine::makeError(
                "{}: an earlier save failed; not saved (the next save writes the whole world)",
                job.store.string());
            d.resync = true;
        }
        // Object models first (named by content: an existing one is this very model), so the
        // committed store never names a payload that is not there.
        for (const engine::scene::PayloadFile& p : job.payloads) {
            const fs::path file = job.store.parent_path() / p.fileName;
            if (!d.status || fs::exists(file, ec)) continue;
            d.status = p.write(file);
        }
        if (d.status) {
            auto report = commit(job, d.whole ? std::nullopt : expected);
            if (report) {
                d.report = *report;
                expected = report->commits;
                // The scene file after the store: if writing it fails, the store holds the new
                // world and the old scene file still names it.
                if (!job.sceneText.empty())
                    d.status = engine::writeFileAtomically(job.savePath, job.sceneText);
            } else {
                d.status = report.error();
                d.resync = !d.whole;  // a mismatch, or a store that could not be opened
                const std::optional<std::uint64_t> before = expected;
                expected.reset();
                // A full disk leaves the store and its counter as they were: keep syncing.
                if (auto s = engine::world::RegionStore::open(job.store, false);
                    s && !d.whole && before && s->info().commits == *before) {
                    d.resync = false;
                    expected = before;
                }
            }
        }
        d.workerMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        lock.lock();
        if (expected)
            mCommits[job.store] = *expected;
        else
            mCommits.erase(job.store);
        mDone.emplace_back(std::move(d), std::move(job.keys));
        mWorking = false;
        if (mQueue.empty()) mIdle.notify_all();
    }
}

}  // namespace game
