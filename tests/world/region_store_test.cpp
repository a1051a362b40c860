// The region store: rows by key, one transaction per commit, files that are not stores (or are
// damaged) refused with one line, and a full disk during a commit keeping the previous state.
#include "world/region_store.h"

#include <fstream>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/hash.h"
#include "io/vdb_test_util.h"
#include "scene/store_world.h"
#include "world/random_worlds.h"

namespace {

using namespace engine::world;
namespace fs = std::filesystem;

engine::world::Scene makeScene(std::uint64_t seed, glm::ivec3 size = {160, 48, 160}) {
    engine::world::Scene scene;
    scene.name = "store_test";
    for (int i = 0; i < 4; ++i) scene.palette.add({"m" + std::to_string(i), glm::vec3(0.2f * i)});
    scene.grid = testing_worlds::makeWorld(testing_worlds::Kind::Mixed, seed, size);
    // makeWorld draws ids up to 255: fold them into the palette.
    BrickGrid folded(size);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                if (MaterialId m = scene.grid.get({x, y, z}))
                    folded.set({x, y, z}, MaterialId(1 + m % 4));
    scene.grid = std::move(folded);
    scene.cameras.push_back({"a", {1, 2, 3}, {4, 5, 6}, 50.0f});
    return scene;
}

TEST(RegionStore, CommitsAndReadsRegionsByKey) {
    vox_test::ScratchDir dir("store");
    const fs::path path = dir / "w.db";
    auto store = RegionStore::openOrCreate(path, {256, 128, 256});
    ASSERT_TRUE(store.ok()) << store.error().message;
    EXPECT_TRUE(RegionStore::isStore(path));
    BrickGrid grid({256, 128, 256});
    grid.set({3, 4, 5}, 1);
    grid.set({200, 4, 5}, 2);
    StoreCommit c;
    c.put.push_back(encodeRegion(snapshotRegion(grid, {0, 0, 0})));
    c.put.push_back(encodeRegion(snapshotRegion(grid, {1, 0, 0})));
    c.sceneKeys.push_back({"world", "[world]\nsize = [256, 128, 256]\n"});
    ASSERT_TRUE(store->commit(c).ok());
    EXPECT_EQ(store->info().commits, 1u);
    auto rows = store->listRegions();
    ASSERT_TRUE(rows.ok());
    EXPECT_EQ(rows->size(), 2u);
    auto one = store->readRegion({1, 0, 0});
    ASSERT_TRUE(one.ok() && one->has_value());
    auto absent = store->readRegion({1, 0, 1});
    ASSERT_TRUE(absent.ok());
    EXPECT_FALSE(absent->has_value());
    // Erased in a later commit.
    ASSERT_TRUE(store->commit({.erase = {{1, 0, 0}}}).ok());
    EXPECT_EQ(store->listRegions()->size(), 1u);
    auto check = store->integrityCheck();
    ASSERT_TRUE(check.ok());
    EXPECT_EQ(*check, "");
}

void expectOneLine(const std::string& message, const fs::path& file) {
    EXPECT_TRUE(vox_test::isOneLineNamingFile(message, file)) << message;
}

TEST(RegionStore, RefusesFilesThatAreNotStoresOrAreDamaged) {
    vox_test::ScratchDir dir("bad");
    const engine::world::Scene scene = makeScene(1);
    const fs::path good = dir / "good.db";
    ASSERT_TRUE(engine::scene::writeWorldStore(scene, good).ok());
    const std::uint64_t size = fs::file_size(good);

    auto write = [&](const std::string& name, const std::string& bytes) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
        return dir / name;
    };
    std::string all;
    {
        std::ifstream in(good, std::ios::binary);
        all.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::vector<fs::path> bad = {write("text.db", "[world]\nsize = [8, 8, 8]\n"),
                                 write("empty.db", ""), write("header.db", all.substr(0, 100))};
    for (std::uint64_t cut : {size / 2, size - 1, std::uint64_t(4096)})
        bad.push_back(write("cut" + std::to_string(cut) + ".db", all.substr(0, cut)));
    // Random bytes over the pages after the header: refused with one line, or (if they only hit
    // free space) read; never a crash.
    for (std::uint64_t seed = 0; seed < 8; ++seed) {
        std::string damaged = all;
        engine::Rng rng(seed);
        for (std::size_t i = 4096 + seed * 7; i < damaged.size(); i += 97)
            damaged[i] = char(rng.nextU32());
        const fs::path p = write("damaged" + std::to_string(seed) + ".db", damaged);
        auto loaded = engine::scene::loadWorldStore(p);
        if (!loaded) expectOneLine(loaded.error().message, p);
    }
    for (const fs::path& p : bad) {
        auto loaded = engine::scene::loadWorldStore(p);
        ASSERT_FALSE(loaded.ok()) << p;
        expectOneLine(loaded.error().message, p);
    }
    // A file that is not a store is never overwritten by a write.
    auto refused = engine::scene::writeWorldStore(scene, dir / "text.db");
    ASSERT_FALSE(refused.ok());
    expectOneLine(refused.error().message, dir / "text.db");
}

TEST(RegionStore, OneVoxelEditCommitsOneRegion) {
    vox_test::ScratchDir dir("edit");
    engine::world::Scene scene = makeScene(2, {512, 64, 512});
    const fs::path path = dir / "w.db";
    ASSERT_TRUE(engine::scene::writeWorldStore(scene, path).ok());
    const std::uint64_t rowsBefore = RegionStore::open(path, false)->listRegions()->size();
    const std::uint32_t saved = scene.grid.closeEditEpoch();
    // A voxel in a corner of a region (on the boundary of four others).
    const glm::ivec3 p(kRegionCells * 8 - 1, 10, kRegionCells * 8);
    scene.grid.set(p, MaterialId(scene.grid.get(p) % 4 + 1));
    const std::vector<RegionKey> dirty = scene.grid.regionsEditedAfter(saved);
    ASSERT_EQ(dirty.size(), 1u);
    auto report = engine::scene::commitSnapshot(engine::scene::snapshotStore(scene, dirty, false),
                                                path, std::uint64_t(1));
    ASSERT_TRUE(report.ok()) << report.error().message;
    EXPECT_LE(report->regionsWritten + report->regionsErased, 2u);
    EXPECT_EQ(report->regionsWritten, 1u);
    EXPECT_EQ(RegionStore::open(path, false)->listRegions()->size(), rowsBefore);
    auto back = engine::scene::loadWorldStore(path);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(back->grid == scene.grid);
}

// A child process whose file size limit makes the save's writes fail (EFBIG, as on a full disk).
TEST(RegionStore, FullDiskDuringSaveKeepsThePreviousState) {
    vox_test::ScratchDir dir("full");
    engine::world::Scene scene = makeScene(3, {256, 64, 256});
    const fs::path path = dir / "w.db";
    ASSERT_TRUE(engine::scene::writeWorldStore(scene, path).ok());
    const engine::world::Scene before = engine::scene::loadWorldStore(path).value();

    int pipeFd[2];
    ASSERT_EQ(::pipe(pipeFd), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::close(pipeFd[0]);
        ::signal(SIGXFSZ, SIG_IGN);
        rlimit limit{fs::file_size(path) + 16384, RLIM_INFINITY};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        // Every region rewritten with noise: far more than the limit allows.
        engine::world::Scene edited = before;
        engine::Rng rng(9);
        for (int z = 0; z < 256; ++z)
            for (int x = 0; x < 256; ++x)
                for (int y = 0; y < 16; ++y)
                    edited.grid.set({x, y, z}, MaterialId(rng.uniformInt(1, 4)));
        auto r = engine::scene::commitSnapshot(
            engine::scene::snapshotStore(edited, {}, /*whole=*/true), path);
        const std::string message = r ? std::string("saved") : r.error().message;
        (void)!::write(pipeFd[1], message.data(), message.size());
        ::_exit(r ? 1 : 0);
    }
    ::close(pipeFd[1]);
    std::string message;
    char buffer[512];
    ssize_t n;
    while ((n = ::read(pipeFd[0], buffer, sizeof buffer)) > 0) message.append(buffer, n);
    ::close(pipeFd[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << message;
    expectOneLine(message, path);
    EXPECT_NE(message.find("keeps its previous state"), std::string::npos) << message;
    auto store = RegionStore::open(path, false);
    ASSERT_TRUE(store.ok());
    EXPECT_EQ(store->integrityCheck().value(), "");
    auto after = engine::scene::loadWorldStore(path);
    ASSERT_TRUE(after.ok()) << after.error().message;
    EXPECT_TRUE(after->grid == before.grid);
}

}  // namespace
