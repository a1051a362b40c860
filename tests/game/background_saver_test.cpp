// vox play's saves: the first save to a file writes the whole world, later ones only the regions
// edited since; a store changed by another writer is never written over with a partial save; and
// a save killed (SIGKILL) at a random moment leaves a store that opens, passes SQLite's integrity
// check, and holds every region's previous or new state — all of them the same save's.
#include "game/background_saver.h"

#include <cstdlib>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "core/hash.h"
#include "io/vdb_test_util.h"
#include "scene/generators/store_keys.h"
#include "scene/scene_file.h"
#include "world/region_store.h"

namespace {

namespace fs = std::filesystem;
using engine::world::MaterialId;
using engine::world::RegionKey;
using engine::world::Scene;

Scene sandbox() {
    auto scene = engine::scene::loadSceneFile(engine::scene::resolveWorldPath("sandbox").value());
    EXPECT_TRUE(scene.ok());
    return std::move(*scene);
}

game::BackgroundSaver::Done saveAndWait(game::BackgroundSaver& saver, Scene& scene,
                                        const fs::path& p, std::uint64_t version = 1) {
    auto r = saver.request(scene, p, false, version);
    EXPECT_TRUE(r.ok()) << r.error().message;
    saver.waitIdle();
    auto done = saver.poll(scene);
    EXPECT_EQ(done.size(), 1u);
    return done.empty() ? game::BackgroundSaver::Done{} : done.back();
}

}  // namespace

namespace game {

TEST(BackgroundSaver, FirstSaveIsWholeThenOnlyEditedRegions) {
    vox_test::ScratchDir dir("saver");
    Scene scene = sandbox();
    BackgroundSaver saver;
    const fs::path save = dir / "w.toml";
    auto first = saveAndWait(saver, scene, save);
    ASSERT_TRUE(first.status.ok()) << first.status.error().message;
    EXPECT_TRUE(first.whole);
    EXPECT_GT(first.report.regionsWritten, 1u);

    scene.grid.set({20, 30, 40}, 1);
    auto second = saveAndWait(saver, scene, save, 2);
    ASSERT_TRUE(second.status.ok()) << second.status.error().message;
    EXPECT_FALSE(second.whole);
    EXPECT_EQ(second.report.regionsWritten + second.report.regionsErased, 1u);

    // The scene file names the store and reopens as the saved world.
    EXPECT_TRUE(engine::scene::sceneFileMarked(save, engine::scene::kSaveMarker));
    auto back = engine::scene::loadSceneFile(save);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(back->grid == scene.grid);
    EXPECT_EQ(engine::scene::storeOfScene(*back), dir / "w.db");

    // Reopened, the world saves back incrementally; nothing edited: no region.
    BackgroundSaver again;
    again.worldLoaded(*back, dir / "w.db");
    auto none = saveAndWait(again, *back, save, 3);
    ASSERT_TRUE(none.status.ok()) << none.status.error().message;
    EXPECT_FALSE(none.whole);
    EXPECT_EQ(none.report.regionsWritten, 0u);
}

TEST(BackgroundSaver, StoreChangedByAnotherWriterIsNotPatched) {
    vox_test::ScratchDir dir("other");
    Scene scene = sandbox();
    BackgroundSaver saver;
    const fs::path save = dir / "w.db";
    ASSERT_TRUE(saveAndWait(saver, scene, save).status.ok());
    {
        auto other = engine::world::RegionStore::open(save, true);
        ASSERT_TRUE(other.ok());
        ASSERT_TRUE(other->commit({}).ok());  // another process's commit
    }
    scene.grid.set({1, 1, 1}, 1);
    auto refused = saveAndWait(saver, scene, save, 2);
    ASSERT_FALSE(refused.status.ok());
    EXPECT_NE(refused.status.error().message.find("another writer"), std::string::npos);
    auto whole = saveAndWait(saver, scene, save, 3);
    ASSERT_TRUE(whole.status.ok()) << whole.status.error().message;
    EXPECT_TRUE(whole.whole);
    EXPECT_TRUE(engine::scene::loadWorldStore(save)->grid == scene.grid);
}

// The saver keeps its store open across saves (no WAL checkpoint per save): a store file
// replaced since (vox import renames a new file into place) must not be written through the old
// connection into the unlinked file — the save is refused and the next one writes the whole world.
TEST(BackgroundSaver, StoreFileReplacedSinceIsNotPatched) {
    vox_test::ScratchDir dir("replaced");
    Scene scene = sandbox();
    BackgroundSaver saver;
    const fs::path save = dir / "w.db";
    ASSERT_TRUE(saveAndWait(saver, scene, save).status.ok());
    scene.grid.set({1, 1, 1}, 1);
    ASSERT_TRUE(saveAndWait(saver, scene, save, 2).status.ok());  // the connection is cached now
    {
        // Another store renamed over it; its counter differs from the saver's.
        const fs::path other = dir / "other.db";
        auto made = engine::world::RegionStore::openOrCreate(other, scene.grid.sizeInVoxels());
        ASSERT_TRUE(made.ok());
    }
    // As vox import does: no log of the old file may be replayed into the new one.
    for (const char* suffix : {"-wal", "-shm"}) fs::remove(save.string() + suffix);
    fs::rename(dir / "other.db", save);
    scene.grid.set({2, 2, 2}, 1);
    auto refused = saveAndWait(saver, scene, save, 3);
    ASSERT_FALSE(refused.status.ok());
    EXPECT_NE(refused.status.error().message.find("another writer"), std::string::npos)
        << refused.status.error().message;
    auto whole = saveAndWait(saver, scene, save, 4);
    ASSERT_TRUE(whole.status.ok()) << whole.status.error().message;
    EXPECT_TRUE(whole.whole);
    EXPECT_TRUE(engine::scene::loadWorldStore(save)->grid == scene.grid);
}

// Markers: 16 voxels in each of three regions spell the number of the save that wrote them.
const glm::ivec3 kMarkers[] = {{1, 60, 1}, {130, 60, 1}, {130, 60, 130}};
constexpr MaterialId kZero = 1, kOne = 2;

void writeMarkers(engine::world::BrickGrid& grid, std::uint32_t n) {
    for (const glm::ivec3& m : kMarkers)
        for (int b = 0; b < 16; ++b) grid.set(m + glm::ivec3(b, 0, 0), (n >> b) & 1 ? kOne : kZero);
}

// The save number each marker region holds (-1: unreadable).
std::vector<int> readMarkers(const engine::world::BrickGrid& grid) {
    std::vector<int> out;
    for (const glm::ivec3& m : kMarkers) {
        int n = 0;
        for (int b = 0; b < 16; ++b) {
            const MaterialId v = grid.get(m + glm::ivec3(b, 0, 0));
            if (v != kZero && v != kOne) return {-1};
            n |= (v == kOne) << b;
        }
        out.push_back(n);
    }
    return out;
}

// VOX_STORE_CRASH_RUNS sets the number of kills (200 for the acceptance:
// tools/store_crash_test.sh).
TEST(BackgroundSaver, KilledDuringSavesLeavesPreviousOrNewState) {
    vox_test::ScratchDir dir("crash");
    const char* env = std::getenv("VOX_STORE_CRASH_RUNS");
    const int runs = env ? std::atoi(env) : 12;
    engine::Rng rng(2024);
    Scene base = sandbox();
    writeMarkers(base.grid, 0);
    const fs::path path = dir / "w.db";
    ASSERT_TRUE(engine::scene::writeWorldStore(base, path).ok());
    for (int run = 0; run < runs; ++run) {
        int fd[2];
        ASSERT_EQ(::pipe(fd), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            ::close(fd[0]);
            auto scene = engine::scene::loadWorldStore(path);
            if (!scene) ::_exit(2);
            BackgroundSaver saver;
            saver.worldLoaded(*scene, path);
            std::uint32_t n = std::uint32_t(readMarkers(scene->grid)[0]);
            engine::Rng edits(run);
            for (;;) {
                ++n;
                writeMarkers(scene->grid, n);
                // More edited regions than the markers', so a commit spans many pages.
                for (int i = 0; i < 64; ++i)
                    scene->grid.set({int(edits.nextU32() % 256), 40 + int(edits.nextU32() % 20),
                                     int(edits.nextU32() % 256)},
                                    MaterialId(1 + edits.nextU32() % 3));
                if (!saver.request(*scene, path, false, n)) ::_exit(3);
                saver.waitIdle();
                for (auto& d : saver.poll(*scene))
                    if (!d.status) ::_exit(4);
                if (::write(fd[1], &n, sizeof n) != sizeof n) ::_exit(5);
            }
        }
        ::close(fd[1]);
        std::this_thread::sleep_for(std::chrono::microseconds(rng.nextU32() % 150000));
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status))
            << "run " << run << ": the child ended by itself, status " << status;
        std::uint32_t reported = 0, n = 0;
        while (::read(fd[0], &n, sizeof n) == sizeof n) reported = n;
        ::close(fd[0]);

        auto store = engine::world::RegionStore::open(path, false);
        ASSERT_TRUE(store.ok()) << "run " << run << ": " << store.error().message;
        auto check = store->integrityCheck();
        ASSERT_TRUE(check.ok());
        ASSERT_EQ(*check, "") << "run " << run;
        auto scene = engine::scene::loadWorldStore(path);
        ASSERT_TRUE(scene.ok()) << "run " << run << ": " << scene.error().message;
        const std::vector<int> markers = readMarkers(scene->grid);
        ASSERT_EQ(markers.size(), 3u) << "run " << run;
        // One save's state in every region (atomic as a whole); the last one reported, or the
        // one being committed when the kill came. (A run starts from the previous run's state.)
        EXPECT_EQ(markers[0], markers[1]) << "run " << run;
        EXPECT_EQ(markers[0], markers[2]) << "run " << run;
        if (reported > 0) {
            EXPECT_GE(markers[0], int(reported)) << "run " << run;
            EXPECT_LE(markers[0], int(reported) + 1) << "run " << run;
        }
    }
}

}  // namespace game
