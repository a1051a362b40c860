// Saves round-trip exactly, and a save interrupted between writing and renaming (an error,
// or the process dying there) leaves the previous save readable and unchanged.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "game/autosave.h"
#include "game/world_store.h"
#include "world/random_worlds.h"
#include "world/scene_file.h"

using namespace engine::world;
namespace fs = std::filesystem;

namespace {

class TempDir {
public:
    TempDir() {
        char pattern[] = "/tmp/vox_store_XXXXXX";
        mPath = ::mkdtemp(pattern);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    const fs::path& path() const { return mPath; }

private:
    fs::path mPath;
};

Scene makeScene(std::uint64_t seed) {
    Scene scene;
    scene.name = "store \"test\"";
    for (int i = 1; i <= 6; ++i) {
        Material m;
        m.name = fmt::format("m{}", i);
        m.albedo = glm::vec3(0.1f * float(i), 0.33f, 0.7f);
        if (i == 6) {
            m.emissionColor = {1.0f, 0.8f, 0.45f};
            m.emissionStrength = 2.5f;
        }
        scene.palette.add(m);
    }
    scene.grid = testing_worlds::makeWorld(testing_worlds::Kind::Mixed, seed, {48, 40, 56});
    scene.cameras.push_back({"front", {1.5f, 20.25f, -30.0f}, {24.0f, 20.0f, 28.0f}, 47.5f});
    scene.sky.sunRadiance = {2.0f, 1.9f, 1.7f};
    return scene;
}

std::size_t countFiles(const fs::path& dir, const std::string& extension) {
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == extension;
    return n;
}

}  // namespace

TEST(WorldStore, SaveAndLoadRoundTripExactly) {
    TempDir dir;
    Scene scene = makeScene(1);
    auto store = game::makeWorldStore();
    fs::path file = dir.path() / "world.toml";
    ASSERT_TRUE(store->save(scene, file).ok());
    EXPECT_TRUE(store->isSave(file));
    auto loaded = store->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->grid == scene.grid);
    EXPECT_EQ(loaded->name, scene.name);
    EXPECT_TRUE(loaded->palette == scene.palette);
    ASSERT_EQ(loaded->cameras.size(), 1u);
    EXPECT_EQ(loaded->cameras[0].position, scene.cameras[0].position);
    EXPECT_EQ(loaded->cameras[0].target, scene.cameras[0].target);
    EXPECT_EQ(loaded->cameras[0].fovYDegrees, scene.cameras[0].fovYDegrees);
    EXPECT_EQ(loaded->sky.sunRadiance, scene.sky.sunRadiance);
    // The plain scene loader opens it too (vox render SAVE.toml).
    EXPECT_TRUE(loadSceneFile(file).ok());

    // A second save replaces the payload; the old generation is removed.
    scene.grid.set({3, 3, 3}, 2);
    ASSERT_TRUE(store->save(scene, file).ok());
    EXPECT_EQ(countFiles(dir.path(), ".bricks"), 1u);
    auto again = store->load(file);
    ASSERT_TRUE(again.ok());
    EXPECT_TRUE(again->grid == scene.grid);
}

TEST(WorldStore, FailureBetweenWriteAndRenameLeavesThePreviousSaveReadable) {
    TempDir dir;
    fs::path file = dir.path() / "world.toml";
    Scene first = makeScene(2);
    ASSERT_TRUE(game::makeWorldStore()->save(first, file).ok());

    Scene second = makeScene(3);
    bool called = false;
    game::SaveFaults faults;
    faults.beforeCommit = [&]() -> engine::Status {
        called = true;
        return engine::makeError("simulated failure before rename");
    };
    engine::Status s = game::makeWorldStore(faults)->save(second, file);
    EXPECT_TRUE(called);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("simulated failure"), std::string::npos);

    auto loaded = game::makeWorldStore()->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->grid == first.grid);
    EXPECT_FALSE(loaded->grid == second.grid);
    EXPECT_EQ(countFiles(dir.path(), ".bricks"), 1u);  // the aborted save's payload is gone
}

TEST(WorldStore, ProcessDyingBetweenWriteAndRenameLeavesThePreviousSaveReadable) {
    // Fork (the "fast" style) so the child dies inside this test's folder; it only does file
    // I/O before _exit, so forking a process with driver threads is harmless here.
    GTEST_FLAG_SET(death_test_style, "fast");
    TempDir dir;
    fs::path file = dir.path() / "world.toml";
    Scene first = makeScene(4);
    ASSERT_TRUE(game::makeWorldStore()->save(first, file).ok());

    Scene second = makeScene(5);
    game::SaveFaults faults;
    faults.beforeCommit = []() -> engine::Status { ::_exit(3); };  // killed mid-save
    EXPECT_EXIT((void)game::makeWorldStore(faults)->save(second, file), ::testing::ExitedWithCode(3), "");

    auto loaded = game::makeWorldStore()->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->grid == first.grid);
    // The dead save left its new payload and temporary file behind; the next save tidies the
    // payload up and commits normally.
    EXPECT_EQ(countFiles(dir.path(), ".bricks"), 2u);
    ASSERT_TRUE(game::makeWorldStore()->save(second, file).ok());
    EXPECT_EQ(countFiles(dir.path(), ".bricks"), 1u);
    auto after = game::makeWorldStore()->load(file);
    ASSERT_TRUE(after.ok());
    EXPECT_TRUE(after->grid == second.grid);
}

TEST(WorldStore, CorruptPayloadIsAnErrorNamingTheFile) {
    TempDir dir;
    fs::path file = dir.path() / "world.toml";
    ASSERT_TRUE(game::makeWorldStore()->save(makeScene(6), file).ok());
    fs::path payload;
    for (const auto& e : fs::directory_iterator(dir.path()))
        if (e.path().extension() == ".bricks") payload = e.path();
    ASSERT_FALSE(payload.empty());
    {
        std::fstream f(payload, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(200);
        f.put('\x7f');
    }
    auto loaded = game::makeWorldStore()->load(file);
    ASSERT_FALSE(loaded.ok());
    EXPECT_NE(loaded.error().message.find("world.toml:"), std::string::npos) << loaded.error().message;
    EXPECT_NE(loaded.error().message.find("checksum"), std::string::npos) << loaded.error().message;

    fs::resize_file(payload, 100);
    loaded = game::makeWorldStore()->load(file);
    ASSERT_FALSE(loaded.ok());
    EXPECT_NE(loaded.error().message.find("truncated"), std::string::npos) << loaded.error().message;
}

TEST(WorldStore, NeverOverwritesAHandWrittenSceneFile) {
    TempDir dir;
    fs::path file = dir.path() / "mine.toml";
    std::ofstream(file) << "[world]\nsize = [8, 8, 8]\n";
    EXPECT_FALSE(game::makeWorldStore()->isSave(file));
    engine::Status s = game::makeWorldStore()->save(makeScene(7), file);
    EXPECT_FALSE(s.ok());
    std::ifstream in(file);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first, "[world]");
}

TEST(Autosave, DueAfterTheIntervalOnlyWhenTheWorldChanged) {
    game::Autosave autosave(180.0);
    EXPECT_FALSE(autosave.due(10.0, 0));    // nothing changed
    EXPECT_FALSE(autosave.due(10.0, 3));    // changed, too early
    EXPECT_TRUE(autosave.due(180.0, 3));
    autosave.written(180.0, 3);
    EXPECT_FALSE(autosave.due(400.0, 3));   // unchanged since written
    EXPECT_FALSE(autosave.due(300.0, 4));
    EXPECT_TRUE(autosave.due(360.0, 4));
    autosave.postpone(360.0);               // a failed write: retry one interval later
    EXPECT_FALSE(autosave.due(400.0, 4));
    EXPECT_TRUE(autosave.due(540.0, 4));
    EXPECT_FALSE(game::Autosave(0.0).due(1e9, 7));  // disabled
    EXPECT_EQ(game::autosavePath("saves/city.toml"), fs::path("saves/city.autosave.toml"));
}
