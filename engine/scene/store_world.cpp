#include "scene/store_world.h"

#include <chrono>
#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/progress.h"
#include "scene/generators/store_keys.h"
#include "scene/scene_file.h"
#include "world/region_store.h"

namespace engine::scene {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// The order scene keys are joined in: the reader does not care, a reader of the text does.
constexpr const char* kKeyOrder[] = {"world", "material", "object", "camera",
                                     "sky",   "indirect", "path"};

std::string regionWhere(const fs::path& path, world::RegionKey k) {
    return fmt::format("{}: region ({}, {}, {})", path.string(), k.x, k.y, k.z);
}

bool keyInside(world::RegionKey k, glm::ivec3 count) {
    return glm::all(glm::greaterThanEqual(k.vec(), glm::ivec3(0))) &&
           glm::all(glm::lessThan(k.vec(), count));
}

// Every region of a grid, in key order, reporting progress as `task` (core/progress.h).
template <typename F>
void forEachRegionKey(glm::ivec3 sizeInCells, int regionCells, std::string_view task, F&& f) {
    const glm::ivec3 n = world::regionCount(sizeInCells, regionCells);
    const std::uint64_t total = std::uint64_t(n.x) * n.y * n.z;
    std::uint64_t done = 0;
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) {
                f(world::RegionKey{x, y, z});
                reportProgress(task, ++done, total);
            }
}

// Progress through a store's rows, which RegionStore::forEachRegion gives in z, y, x order: the
// position of the row's key among all the world's regions in that order.
void reportRowProgress(std::string_view task, world::RegionKey k, glm::ivec3 count) {
    const std::uint64_t total = std::uint64_t(count.x) * count.y * count.z;
    const std::uint64_t at = (std::uint64_t(k.z) * count.y + k.y) * count.x + k.x;
    if (at + 1 < total) reportProgress(task, at + 1, total);  // the end is reported once, after
}

}  // namespace

SceneKeys sceneKeysOf(const world::Scene& scene,
                      const std::vector<std::vector<world::GeneratorRecord>>* objectGenerators) {
    const std::vector<world::GeneratorRecord> none;
    const std::string text =
        sceneText(scene, {.generators = &none, .objectGenerators = objectGenerators});
    // The writer puts every key and value on one line (strings quoted with escapes), so a line
    // that starts with '[' is a table header; its first name part is the scene key.
    SceneKeys keys;
    std::string* current = nullptr;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string_view line(text.data() + start, end - start);
        if (!line.empty() && line[0] == '[') {
            const std::size_t from = line.find_first_not_of('[');
            const std::size_t to = line.find_first_of(".]", from);
            const std::string name(line.substr(from, to - from));
            auto it = std::find_if(keys.begin(), keys.end(),
                                   [&](const auto& k) { return k.first == name; });
            current = it != keys.end() ? &it->second : &keys.emplace_back(name, "").second;
            if (!current->empty()) *current += '\n';
        }
        if (current && !line.empty()) {
            *current += line;
            *current += '\n';
        }
        start = end + 1;
    }
    return keys;
}

std::string sceneTextOfKeys(const std::map<std::string, std::string>& keys) {
    std::string text;
    auto add = [&](const std::string& t) {
        if (!text.empty()) text += '\n';
        text += t;
    };
    for (const char* name : kKeyOrder)
        if (auto it = keys.find(name); it != keys.end()) add(it->second);
    for (const auto& [name, t] : keys)
        if (std::find_if(std::begin(kKeyOrder), std::end(kKeyOrder),
                         [&](const char* k) { return name == k; }) == std::end(kKeyOrder))
            add(t);
    return text;
}

StoreSnapshot snapshotStore(
    const world::Scene& scene, std::span<const world::RegionKey> regions, bool whole,
    const std::vector<std::vector<world::GeneratorRecord>>* objectGenerators) {
    StoreSnapshot s;
    s.whole = whole;
    s.worldSizeInVoxels = scene.grid.sizeInVoxels();
    s.sceneKeys = sceneKeysOf(scene, objectGenerators);
    if (whole) {
        forEachRegionKey(scene.grid.sizeInCells(), world::kRegionCells, "copying world regions",
                         [&](world::RegionKey k) {
                             world::RegionSnapshot r = world::snapshotRegion(scene.grid, k);
                             if (!r.empty()) s.regions.push_back(std::move(r));
                         });
    } else {
        for (const world::RegionKey& k : regions)
            s.regions.push_back(world::snapshotRegion(scene.grid, k));
    }
    return s;
}

Result<StoreWriteReport> commitSnapshot(const StoreSnapshot& snapshot, const fs::path& path,
                                        std::optional<std::uint64_t> expectedCommits) {
    auto store = world::RegionStore::openOrCreate(path, snapshot.worldSizeInVoxels);
    if (!store) return store.error();
    return commitSnapshot(snapshot, *store, expectedCommits);
}

Result<StoreWriteReport> commitSnapshot(const StoreSnapshot& snapshot, world::RegionStore& store,
                                        std::optional<std::uint64_t> expectedCommits) {
    const fs::path& path = store.path();
    StoreWriteReport report;
    const auto t0 = Clock::now();
    world::StoreCommit change;
    change.replaceAll = snapshot.whole;
    change.worldSizeInVoxels = snapshot.worldSizeInVoxels;
    change.sceneKeys = snapshot.sceneKeys;
    for (const world::RegionSnapshot& r : snapshot.regions) {
        if (r.empty()) {
            change.erase.push_back(r.key);
            continue;
        }
        change.put.push_back(world::encodeRegion(r));
        report.rawBytes += change.put.back().rawBytes;
        report.storedBytes += change.put.back().blob.size();
    }
    report.encodeMs = msSince(t0);
    const auto t1 = Clock::now();
    if (!snapshot.whole && store.info().regionCells != world::kRegionCells)
        return makeError("{}: regions of {} cells, saves write {}: save the whole world",
                         path.string(), store.info().regionCells, world::kRegionCells);
    // The counter is checked inside the transaction (RegionStore::commit), so a writer that
    // commits between our check and our write cannot slip through.
    if (!snapshot.whole) change.expectedCommits = expectedCommits;
    if (Status s = store.commit(change); !s) return s.error();
    report.commitMs = msSince(t1);
    report.commits = store.info().commits;
    report.regionsWritten = change.put.size();
    report.regionsErased = change.erase.size();
    report.fileBytes = store.fileBytes();
    if (auto rows = store.regionRows()) report.regionRows = *rows;
    return report;
}

Result<StoreWriteReport> writeWorldStore(const world::Scene& scene, const fs::path& path,
                                         int regionCells) {
    StoreWriteReport report;
    std::error_code ec;
    const bool exists = fs::exists(path, ec);
    if (exists && !world::RegionStore::isStore(path) &&
        !(fs::is_regular_file(path, ec) && fs::file_size(path, ec) == 0))
        return makeError("{}: not a world store; refusing to overwrite it", path.string());
    // A new file is made under a temporary name, so a crash never leaves a half store at `path`;
    // an existing store is replaced in one transaction (SQLite's own atomic commit).
    const fs::path target = exists ? path : temporaryPathFor(path);
    if (!exists) {
        for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(target.string() + suffix, ec);
    }
    Status status;
    {
        const auto t0 = Clock::now();
        auto store =
            world::RegionStore::openOrCreate(target, scene.grid.sizeInVoxels(), regionCells);
        if (!store) return store.error();
        status = store->begin(/*replaceAll=*/true, regionCells);
        forEachRegionKey(scene.grid.sizeInCells(), regionCells, "writing store regions",
                         [&](world::RegionKey k) {
                             if (!status) return;
                             const world::RegionSnapshot r =
                                 world::snapshotRegion(scene.grid, k, regionCells);
                             if (r.empty()) return;
                             const world::EncodedRegion e = world::encodeRegion(r);
                             report.rawBytes += e.rawBytes;
                             report.storedBytes += e.blob.size();
                             ++report.regionsWritten;
                             status = store->put(e);
                         });
        for (const auto& [name, text] : sceneKeysOf(scene)) {
            if (!status) break;
            status = store->putSceneKey(name, text);
        }
        if (status) status = store->commitTransaction(scene.grid.sizeInVoxels());
        report.encodeMs = msSince(t0);
        report.fileBytes = store->fileBytes();
        report.regionRows = report.regionsWritten;
    }  // closed: SQLite folds the write-ahead log into the file and removes it
    if (!status) {
        if (!exists)
            for (const char* suffix : {"", "-wal", "-shm"})
                fs::remove(target.string() + suffix, ec);
        return status.error();
    }
    if (!exists) {
        // A log left by an earlier store of this name (deleted without its log) would be
        // replayed into the new file: remove it before the new file takes the name.
        for (const char* suffix : {"-wal", "-shm"}) fs::remove(path.string() + suffix, ec);
        fs::rename(target, path, ec);
        if (ec) {
            fs::remove(target, ec);
            return makeError("{}: cannot rename the new store into place: {}", path.string(),
                             ec.message());
        }
    }
    std::error_code sizeError;
    report.fileBytes = fs::file_size(path, sizeError);
    return report;
}

Result<world::Scene> loadWorldStore(const fs::path& path, std::optional<world::Box> box,
                                    bool regions) {
    auto store = world::RegionStore::open(path, /*writable=*/false);
    if (!store) return store.error();
    auto keys = store->sceneKeys();
    if (!keys) return keys.error();
    if (!keys->count("world"))
        return makeError("{}: damaged world store: no 'world' scene key", path.string());
    auto scene = loadSceneText(sceneTextOfKeys(*keys), path.string());
    if (!scene) return scene.error();
    const glm::ivec3 size = store->info().worldSizeInVoxels;
    if (scene->grid.sizeInVoxels() != (size + 7) / 8 * 8)
        return makeError("{}: damaged world store: its [world] size does not match its meta",
                         path.string());
    const int rc = store->info().regionCells;
    const glm::ivec3 cells = scene->grid.sizeInCells();
    const glm::ivec3 count = world::regionCount(cells, rc);
    const std::size_t paletteSize = scene->palette.size();
    auto readOne = [&](world::RegionKey key, std::span<const std::uint8_t> blob,
                       world::BrickGrid& grid, glm::ivec3 cellOffset) -> Status {
        const std::string where = regionWhere(path, key);
        if (!keyInside(key, count))
            return makeError("{}: outside the world's {}x{}x{} regions", where, count.x, count.y,
                             count.z);
        auto region = world::decodeRegion(key, blob, world::regionCells(key, cells, rc).size(),
                                          paletteSize, where);
        if (!region) return region.error();
        world::writeRegion(*region, grid, rc, cellOffset);
        return {};
    };
    if (!regions) {
        // streamed: the grid stays empty
    } else if (!box) {
        if (Status s = store->forEachRegion([&](world::RegionKey key, auto blob) {
                if (keyInside(key, count)) reportRowProgress("reading store regions", key, count);
                return readOne(key, blob, scene->grid, glm::ivec3(0));
            });
            !s)
            return s.error();
        const std::uint64_t total = std::uint64_t(count.x) * count.y * count.z;
        reportProgress("reading store regions", total, total);
    } else {
        const world::Box b = box->intersect(scene->grid.bounds());
        if (b.empty())
            return makeError("{}: the box lies outside the world ({}x{}x{})", path.string(), size.x,
                             size.y, size.z);
        const glm::ivec3 lo = b.min / world::kBrickDim;
        const glm::ivec3 hi = (b.max + world::kBrickDim - 1) / world::kBrickDim;
        world::BrickGrid grid((hi - lo) * world::kBrickDim);
        // Only the regions meeting the box are read, each by its key.
        const glm::ivec3 rlo = lo / rc, rhi = (hi - 1) / rc;
        for (int z = rlo.z; z <= rhi.z; ++z)
            for (int y = rlo.y; y <= rhi.y; ++y)
                for (int x = rlo.x; x <= rhi.x; ++x) {
                    auto blob = store->readRegion({x, y, z});
                    if (!blob) return blob.error();
                    if (!*blob) continue;
                    if (Status s = readOne({x, y, z}, **blob, grid, lo); !s) return s.error();
                }
        scene->grid = std::move(grid);
    }
    scene->grid.clearDirty();
    scene->generators = {storeGenerator(path.filename().string())};
    scene->sourcePath = path.string();
    return scene;
}

Status readStoreInto(world::Scene& scene, const fs::path& path) {
    auto store = world::RegionStore::open(path, /*writable=*/false);
    if (!store) return store.error();
    auto keys = store->sceneKeys();
    if (!keys) return keys.error();
    // The store's palette: its material key under a stand-in [world] (its own size would
    // allocate a grid only to be dropped).
    std::map<std::string, std::string> paletteKeys{{"world", "[world]\nsize = [8, 8, 8]\n"}};
    if (auto it = keys->find("material"); it != keys->end()) paletteKeys.insert(*it);
    auto own = loadSceneText(sceneTextOfKeys(paletteKeys), path.string());
    if (!own) return own.error();
    // Store ids to the scene's, by name.
    std::vector<world::MaterialId> remap(own->palette.size(), world::kEmpty);
    bool identity = true;
    for (std::size_t i = 1; i < own->palette.size(); ++i) {
        const world::Material& m = own->palette[world::MaterialId(i)];
        auto id = scene.palette.find(m.name);
        if (!id) id = scene.palette.add(m);
        if (!id)
            return makeError("{}: material '{}' does not fit the palette (at most {})",
                             path.string(), m.name, world::kMaxMaterials - 1);
        remap[i] = *id;
        identity = identity && *id == i;
    }
    const int rc = store->info().regionCells;
    const glm::ivec3 cells = (store->info().worldSizeInVoxels + 7) / 8;
    const glm::ivec3 count = world::regionCount(cells, rc);
    const std::uint64_t total = std::uint64_t(count.x) * count.y * count.z;
    Status read = store->forEachRegion([&](world::RegionKey key, auto blob) -> Status {
        const std::string where = regionWhere(path, key);
        if (!keyInside(key, count))
            return makeError("{}: outside the world's {}x{}x{} regions", where, count.x, count.y,
                             count.z);
        auto region = world::decodeRegion(key, blob, world::regionCells(key, cells, rc).size(),
                                          own->palette.size(), where);
        if (!region) return region.error();
        if (!identity) {
            for (std::uint32_t& c : region->cells)
                if (c & shared::CELL_HOMOGENEOUS)
                    c = shared::CELL_HOMOGENEOUS | remap[world::BrickGrid::cellMaterial(c)];
            for (world::BrickVoxels& b : region->bricks)
                for (world::MaterialId& m : b) m = remap[m];
        }
        world::writeRegion(*region, scene.grid, rc);
        reportRowProgress("reading store regions", key, count);
        return {};
    });
    reportProgress("reading store regions", total, total);
    return read;
}

}  // namespace engine::scene
