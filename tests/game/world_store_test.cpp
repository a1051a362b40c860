// Saves (scene file + .vdb payload) round-trip exactly, after any number of edits, and a save
// that fails — writing the payload, or between writing the scene file and renaming it (an
// error, or the process dying there) — leaves the previous save readable and unchanged.
#include "game/world_store.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <set>
#include <sys/wait.h>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/hash.h"
#include "game/autosave.h"
#include "io/vdb_export.h"
#include "io/vdb_import.h"
#include "io/vox_export.h"
#include "scene/scene_equality.h"
#include "scene/scene_file.h"
#include "scene/scene_lighting.h"
#include "world/flythrough.h"
#include "world/random_worlds.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace engine::scene;
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

std::set<fs::path> filesIn(const fs::path& dir) {
    std::set<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) files.insert(e.path());
    return files;
}

fs::path onlyPayload(const fs::path& dir) {
    fs::path payload;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".vdb") payload = e.path();
    return payload;
}

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Cell by cell, the encodings too: empty, homogeneous with the same material, or a brick with
// the same voxels (BrickGrid::operator== compares exactly that; this says where they differ).
void expectSameWorld(const Scene& a, const Scene& b, const std::string& what) {
    ASSERT_EQ(a.grid.sizeInCells(), b.grid.sizeInCells()) << what;
    EXPECT_TRUE(a.palette == b.palette) << what;
    EXPECT_EQ(a.voxelSize, b.voxelSize) << what;
    EXPECT_EQ(a.grid.solidVoxels(), b.grid.solidVoxels()) << what;
    EXPECT_EQ(a.grid.homogeneousCells(), b.grid.homogeneousCells()) << what;
    EXPECT_EQ(a.grid.liveBricks(), b.grid.liveBricks()) << what;
    const std::vector<std::uint32_t> ca = a.grid.denseCells(), cb = b.grid.denseCells();
    std::size_t differing = 0;
    for (std::size_t i = 0; i < ca.size(); ++i) {
        bool same =
            BrickGrid::cellIsBrick(ca[i]) == BrickGrid::cellIsBrick(cb[i]) &&
            (BrickGrid::cellIsBrick(ca[i]) ? a.grid.brickVoxels(BrickGrid::cellBrick(ca[i])) ==
                                                 b.grid.brickVoxels(BrickGrid::cellBrick(cb[i]))
                                           : ca[i] == cb[i]);
        differing += !same;
    }
    EXPECT_EQ(differing, 0u) << what << ": cells differ";
    EXPECT_TRUE(a.grid == b.grid) << what;
}

}  // namespace

TEST(WorldStore, SaveAndLoadRoundTripExactly) {
    TempDir dir;
    Scene scene = makeScene(1);
    auto store = game::makeWorldStore();
    fs::path file = dir.path() / "world.toml";
    ASSERT_TRUE(store->save(scene, file).ok());
    EXPECT_TRUE(store->isSave(file));
    // The scene file names the payload with the lossless rule.
    const std::string text = bytesOf(file);
    EXPECT_NE(text.find("type = \"vdb\"\nsource = \"world.1.vdb\"\nrule = \"ids\""),
              std::string::npos)
        << text;
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 1u);
    auto loaded = store->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    expectSameWorld(scene, *loaded, "first save");
    EXPECT_EQ(loaded->name, scene.name);
    EXPECT_EQ(loaded->sourcePath, file.string());  // the scene file, not its payload
    ASSERT_EQ(loaded->cameras.size(), 1u);
    EXPECT_EQ(loaded->cameras[0].position, scene.cameras[0].position);
    EXPECT_EQ(loaded->cameras[0].target, scene.cameras[0].target);
    EXPECT_EQ(loaded->cameras[0].fovYDegrees, scene.cameras[0].fovYDegrees);
    EXPECT_EQ(loaded->sky.sunRadiance, scene.sky.sunRadiance);
    // The plain scene loader opens it too (vox render SAVE.toml), and the payload on its own is
    // a whole world for any OpenVDB reader (vox import, other tools).
    EXPECT_TRUE(loadSceneFile(file).ok());
    auto alone = engine::io::importVdb(dir.path() / "world.1.vdb");
    ASSERT_TRUE(alone.ok()) << alone.error().message;
    expectSameWorld(scene, *alone, "payload imported alone");

    // A second save replaces the payload; the old generation is removed.
    scene.grid.set({3, 3, 3}, 2);
    ASSERT_TRUE(store->save(scene, file).ok());
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 1u);
    EXPECT_TRUE(fs::exists(dir.path() / "world.2.vdb"));
    auto again = store->load(file);
    ASSERT_TRUE(again.ok());
    expectSameWorld(scene, *again, "second save");
}

TEST(WorldStore, RoundTripsBitForBitAfterEdits) {
    // Edits of every kind between saves — single voxels, boxes that make homogeneous cells,
    // carving that frees bricks, a cell emptied whole, a new material — and each save loads back
    // equal to the world in memory, which is then edited further from the loaded copy (as the
    // sandbox does after opening a save).
    TempDir dir;
    fs::path file = dir.path() / "edited.toml";
    Scene scene = makeScene(11);
    scene.voxelSize = 0.25f;
    auto store = game::makeWorldStore();
    engine::Rng rng(2024);
    const glm::ivec3 size = scene.grid.sizeInVoxels();
    auto voxel = [&] {
        return glm::ivec3(rng.uniformInt(0, size.x - 1), rng.uniformInt(0, size.y - 1),
                          rng.uniformInt(0, size.z - 1));
    };
    for (int round = 0; round < 6; ++round) {
        if (round == 3) {
            Material glow{"glow \"new\"", glm::vec3(0.9f, 0.2f, 0.1f), glm::vec3(1.0f, 0.5f, 0.25f),
                          7.5f};
            ASSERT_TRUE(scene.palette.add(glow).has_value());
        }
        const int materials = int(scene.palette.size()) - 1;
        for (int i = 0; i < 300; ++i)
            scene.grid.set(voxel(), MaterialId(rng.uniformInt(0, materials)));
        glm::ivec3 a = voxel(), b = voxel();
        fillBox(scene.grid, Box{glm::min(a, b), glm::max(a, b) + 1},
                MaterialId(rng.uniformInt(1, materials)));
        fillSphere(scene.grid, glm::vec3(voxel()), rng.uniform(2.0f, 9.0f), kEmpty);
        paintSphere(scene.grid, glm::vec3(voxel()), rng.uniform(2.0f, 9.0f),
                    MaterialId(rng.uniformInt(1, materials)));
        scene.grid.writeCellUniform(glm::ivec3(round % 6, 1, 2), kEmpty);
        scene.grid.writeCellUniform(glm::ivec3(1, round % 5, 3), MaterialId(1 + round % materials));
        scene.grid.clearDirty();

        ASSERT_TRUE(store->save(scene, file).ok()) << "round " << round;
        EXPECT_EQ(countFiles(dir.path(), ".vdb"), 1u) << "round " << round;
        auto loaded = store->load(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        expectSameWorld(scene, *loaded, fmt::format("round {}", round));
        scene = std::move(*loaded);
    }
}

TEST(WorldStore, FailureBetweenWriteAndRenameLeavesThePreviousSaveReadable) {
    TempDir dir;
    fs::path file = dir.path() / "world.toml";
    Scene first = makeScene(2);
    ASSERT_TRUE(game::makeWorldStore()->save(first, file).ok());

    const std::string sceneBefore = bytesOf(file), payloadBefore = bytesOf(onlyPayload(dir.path()));

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
    expectSameWorld(first, *loaded, "after the failed save");
    EXPECT_FALSE(loaded->grid == second.grid);
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 1u);  // the aborted save's payload is gone
    EXPECT_EQ(bytesOf(file), sceneBefore);
    EXPECT_EQ(bytesOf(onlyPayload(dir.path())), payloadBefore);
}

TEST(WorldStore, FailedPayloadWriteLeavesThePreviousSaveIntact) {
    TempDir dir;
    fs::path file = dir.path() / "world.toml";
    Scene first = makeScene(8);
    ASSERT_TRUE(game::makeWorldStore()->save(first, file).ok());
    const std::string sceneBefore = bytesOf(file),
                      payloadBefore = bytesOf(dir.path() / "world.1.vdb");

    // The exporter writes WORLD.2.vdb through a temporary file beside it; a folder in the way
    // makes that write fail (as a full disk or a read-only folder would).
    fs::path blocker = engine::temporaryPathFor(dir.path() / "world.2.vdb");
    fs::create_directory(blocker);
    Scene second = makeScene(9);
    engine::Status s = game::makeWorldStore()->save(second, file);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("world.2.vdb"), std::string::npos) << s.error().message;
    EXPECT_EQ(bytesOf(file), sceneBefore);
    EXPECT_EQ(bytesOf(dir.path() / "world.1.vdb"), payloadBefore);
    EXPECT_FALSE(fs::exists(dir.path() / "world.2.vdb"));
    auto loaded = game::makeWorldStore()->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    expectSameWorld(first, *loaded, "after the failed payload write");

    fs::remove(blocker);
    ASSERT_TRUE(game::makeWorldStore()->save(second, file).ok());
    auto after = game::makeWorldStore()->load(file);
    ASSERT_TRUE(after.ok()) << after.error().message;
    expectSameWorld(second, *after, "the next save");
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 1u);
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
    EXPECT_EXIT((void)game::makeWorldStore(faults)->save(second, file),
                ::testing::ExitedWithCode(3), "");

    auto loaded = game::makeWorldStore()->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->grid == first.grid);
    // The dead save left its new payload and temporary file behind; the next save tidies both
    // up and commits normally.
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 2u);
    ASSERT_TRUE(game::makeWorldStore()->save(second, file).ok());
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 1u);
    for (const auto& e : fs::directory_iterator(dir.path()))  // the dead process's temporary too
        EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
    auto after = game::makeWorldStore()->load(file);
    ASSERT_TRUE(after.ok());
    EXPECT_TRUE(after->grid == second.grid);
}

TEST(WorldStore, DamagedOrMissingPayloadIsAnErrorNamingTheFiles) {
    // OpenVDB files carry no checksum, so a flipped bit inside voxel data may go unnoticed; what
    // is caught (cut short, not a VDB file at all, gone) is reported with the scene file's line
    // and the payload's name, never half-loaded.
    TempDir dir;
    fs::path file = dir.path() / "world.toml";
    ASSERT_TRUE(game::makeWorldStore()->save(makeScene(6), file).ok());
    fs::path payload = onlyPayload(dir.path());
    ASSERT_FALSE(payload.empty());
    const std::string full = bytesOf(payload);
    auto expectError = [&](const char* what, const char* message) {
        auto loaded = game::makeWorldStore()->load(file);
        ASSERT_FALSE(loaded.ok()) << what;
        const std::string& e = loaded.error().message;
        EXPECT_NE(e.find("world.toml:"), std::string::npos) << what << ": " << e;
        EXPECT_NE(e.find(payload.filename().string()), std::string::npos) << what << ": " << e;
        EXPECT_NE(e.find(message), std::string::npos) << what << ": " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << what << ": " << e;
    };

    fs::resize_file(payload, full.size() / 2);
    expectError("cut in half", "");
    std::ofstream(payload, std::ios::binary | std::ios::trunc)
        << "not a vdb file at all, just some text";
    expectError("text", "not a VDB file");
    fs::remove(payload);
    expectError("missing", "cannot open");
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

TEST(WorldStore, SavedDragonCityKeepsItsDragonPathAndIndirectSettings) {
    // dragon_city as shipped, plus the lighting settings and flythrough a user may give it.
    fs::path original = fs::path(VOX_SOURCE_DIR) / "worlds" / "dragon_city.toml";
    std::string text = bytesOf(original);
    ASSERT_EQ(text.find("[indirect]"), std::string::npos)
        << "dragon_city has its own [indirect] now: drop this one";
    ASSERT_EQ(text.find("[path]"), std::string::npos)
        << "dragon_city has its own [path] now: drop this one";
    text += R"(
[indirect]
mode = "cache"
rays = 8
alpha = 0.05
filter = false

[path]
fps = 24

[[path.key]]
time = 0.0
position = [96, 14, -20]
target = [96, 26, 90]

[[path.key]]
time = 4.0
position = [150, 60, -30]
target = [104, 20, 96]
fov = 50

[[path.event]]
time = 1.0
type = "light"
material = "shop"
on = false
)";
    TempDir dir;
    fs::path handWritten = dir.path() / "dragon_city.toml";
    std::ofstream(handWritten) << text;
    auto store = game::makeWorldStore();
    auto scene = store->load(handWritten);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    ASSERT_EQ(scene->objects.size(), 1u);

    fs::path file = dir.path() / "saves" / "dragon_city.toml";
    ASSERT_TRUE(store->save(*scene, file).ok());
    auto saved = store->load(file);
    ASSERT_TRUE(saved.ok()) << saved.error().message << "\n" << bytesOf(file);
    EXPECT_EQ(engine::scene::test::sceneDifference(*scene, *saved), "") << bytesOf(file);
    ASSERT_EQ(saved->objects.size(), 1u);
    EXPECT_EQ(saved->objects[0].name, "dragon");
    EXPECT_GT(saved->objects[0].model->solidVoxels(), 0u);
    EXPECT_EQ(saved->objects[0].path.keys().size(), 5u);
    ASSERT_TRUE(saved->path);
    EXPECT_EQ(saved->path->camera.keys().size(), 2u);
    EXPECT_EQ(saved->path->timeline.events().size(), 1u);
    auto lighting = engine::scene::lightingFor(&*saved, {});
    ASSERT_TRUE(lighting.ok()) << lighting.error().message;
    EXPECT_EQ(lighting->indirect, engine::lighting::Indirect::Cache);
    EXPECT_EQ(lighting->cache.raysPerUpdate, 8u);
    EXPECT_FALSE(lighting->cache.filter);
    // Its voxels come from the payload now, not from the city's generators.
    EXPECT_EQ(saved->generators.size(), 1u);
    EXPECT_EQ(saved->generators[0].type, "vdb");
}

TEST(Autosave, DueAfterTheIntervalOnlyWhenTheWorldChanged) {
    game::Autosave autosave(180.0);
    EXPECT_FALSE(autosave.due(10.0, 0));  // nothing changed
    EXPECT_FALSE(autosave.due(10.0, 3));  // changed, too early
    EXPECT_TRUE(autosave.due(180.0, 3));
    autosave.written(180.0, 3);
    EXPECT_FALSE(autosave.due(400.0, 3));  // unchanged since written
    EXPECT_FALSE(autosave.due(300.0, 4));
    EXPECT_TRUE(autosave.due(360.0, 4));
    autosave.postpone(360.0);  // a failed write: retry one interval later
    EXPECT_FALSE(autosave.due(400.0, 4));
    EXPECT_TRUE(autosave.due(540.0, 4));
    EXPECT_FALSE(game::Autosave(0.0).due(1e9, 7));  // disabled
    EXPECT_EQ(game::autosavePath("saves/city.toml"), fs::path("saves/city.autosave.toml"));
}

// A scene file's `name` chose the default save path unchecked: "../../x" saved outside saves/.
TEST(WorldStore, HostileWorldNamesSaveInsideTheSavesFolder) {
    const char* hostile[] = {"../../x", "/etc/passwd", "..",   "a/../../b", "C:\\x\\y",
                             "",        "....",        "x\ny", "./.hidden", "name/with/slashes",
                             "\xff\xfe"};
    for (const char* name : hostile) {
        std::filesystem::path p = game::defaultSavePath(name);
        EXPECT_EQ(p.parent_path(), std::filesystem::path("saves")) << "'" << name << "' -> " << p;
        const std::string file = p.filename().string();
        EXPECT_EQ(file.find_first_of("/\\\n"), std::string::npos) << p;
        EXPECT_NE(file.front(), '.') << p;
        EXPECT_EQ(p.extension(), ".toml") << p;
    }
    EXPECT_EQ(game::defaultSavePath("dragon city"),
              std::filesystem::path("saves/dragon city.toml"));
    EXPECT_EQ(game::defaultSavePath(std::string(300, 'a')).filename().string().size(), 64u + 5u);
}

// A save whose scene file path is a folder says so and writes no payload.
TEST(WorldStore, ASaveOverAFolderSaysSoAndLeavesNoPayload) {
    TempDir dir;
    fs::create_directory(dir.path() / "world.toml");
    engine::Status s = game::makeWorldStore()->save(makeScene(6), dir.path() / "world.toml");
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().message,
              (dir.path() / "world.toml").string() + " is a folder; give a file name to write");
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 0u);
}

// A full disk at each write and fsync of a save in turn: the previous save (scene file and
// payload) stays byte-identical and loads; no new payload is left.
TEST(WorldStore, AFullDiskAtAnyStepOfASaveKeepsThePreviousSave) {
    TempDir dir;
    const fs::path file = dir.path() / "world.toml";
    Scene first = makeScene(10), second = makeScene(11);
    ASSERT_TRUE(game::makeWorldStore()->save(first, file).ok());
    const std::string sceneBefore = bytesOf(file),
                      payloadBefore = bytesOf(dir.path() / "world.1.vdb");
    const std::set<fs::path> filesBefore = filesIn(dir.path());
    int failures = 0;
    for (std::uint64_t n = 0; n < 400; ++n) {
        engine::failWritesAfter(n);
        engine::Status s = game::makeWorldStore()->save(second, file);
        engine::failWritesAfter(std::nullopt);
        if (s.ok()) break;
        ++failures;
        EXPECT_NE(s.error().message.find("No space left on device"), std::string::npos)
            << s.error().message;
        ASSERT_EQ(bytesOf(file), sceneBefore) << "operation " << n;
        ASSERT_EQ(bytesOf(dir.path() / "world.1.vdb"), payloadBefore) << "operation " << n;
        ASSERT_EQ(filesIn(dir.path()), filesBefore) << "operation " << n;
    }
    EXPECT_GE(failures, 3);
    auto loaded = game::makeWorldStore()->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    expectSameWorld(second, *loaded, "after the disk had room again");
}

// vox play X.vox (or X.vdb) plays the file as a world instead of reading it as a scene file
// ("invalid utf-8 sequence"); a save then writes a world of its own.
TEST(WorldStore, LoadsVoxAndVdbFilesAsWorlds) {
    TempDir dir;
    Scene scene = makeScene(3);
    ASSERT_TRUE(engine::io::exportVox(scene, dir.path() / "model.vox").ok());
    ASSERT_TRUE(engine::io::exportVdb(scene, dir.path() / "model.vdb").ok());
    auto store = game::makeWorldStore();
    for (const char* name : {"model.vox", "model.vdb"}) {
        auto loaded = store->load(dir.path() / name);
        ASSERT_TRUE(loaded.ok()) << name << ": " << loaded.error().message;
        EXPECT_EQ(loaded->grid.solidVoxels(), scene.grid.solidVoxels()) << name;
        EXPECT_FALSE(store->isSave(dir.path() / name));
    }
}

// Issue 41, item 1: after its commit a save removed every STEM.<digits>.vdb beside it, and VDB
// sequences are named exactly so (Houdini, Blender, EmberGen: frame.0001.vdb): `vox play --save
// frame.toml` deleted frame.0001 ... frame.0010.vdb. Only the save's own older payloads go.
TEST(WorldStore, AVdbSequenceBesideASaveSurvivesIt) {
    TempDir dir;
    const fs::path file = dir.path() / "frame.toml";
    std::vector<fs::path> sequence;
    for (int i = 1; i <= 10; ++i) {
        sequence.push_back(dir.path() / fmt::format("frame.{:04d}.vdb", i));
        std::ofstream(sequence.back()) << "frame " << i;
    }
    auto store = game::makeWorldStore();
    ASSERT_TRUE(store->save(makeScene(1), file).ok());
    ASSERT_TRUE(store->save(makeScene(2), file).ok());  // its first payload goes, nothing else
    for (int i = 1; i <= 10; ++i)
        EXPECT_EQ(bytesOf(sequence[i - 1]), fmt::format("frame {}", i)) << sequence[i - 1];
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), sequence.size() + 1);
    auto loaded = store->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    expectSameWorld(makeScene(2), *loaded, "the second save");
}

// Issue 41, item 7: two writers of one world (two `vox play` with one --save; a save and an
// import) each picked N = max + 1 and removed the other payloads after their commit, with no
// lock: the scene file could end up naming a payload the other had deleted. Now the second
// writer is refused while the first writes, naming it, and nothing the world names is removed.
TEST(WorldStore, ASecondWriterOfOneWorldIsRefusedWhileTheFirstWrites) {
    TempDir dir;
    const fs::path file = dir.path() / "world.toml";
    int paused[2], resume[2];
    ASSERT_EQ(::pipe(paused), 0);
    ASSERT_EQ(::pipe(resume), 0);
    const pid_t child = ::fork();
    if (child == 0) {
        // The first writer, held between writing its payload and committing.
        game::SaveFaults faults;
        faults.beforeCommit = [&]() -> engine::Status {
            char c = 'p';
            (void)!::write(paused[1], &c, 1);
            (void)!::read(resume[0], &c, 1);
            return {};
        };
        ::_exit(game::makeWorldStore(faults)->save(makeScene(1), file).ok() ? 0 : 1);
    }
    char c = 0;
    ASSERT_EQ(::read(paused[0], &c, 1), 1);
    engine::Status second = game::makeWorldStore()->save(makeScene(2), file);
    (void)!::write(resume[1], "r", 1);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the first writer failed";
    EXPECT_FALSE(second.ok()) << "the second writer was not refused";
    if (!second.ok()) {
        EXPECT_EQ(
            second.error().message,
            fmt::format("{} is in use by another save or import (pid {})", file.string(), child));
    }
    auto loaded = game::makeWorldStore()->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    expectSameWorld(makeScene(1), *loaded, "the first writer's save");
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 1u);
}

// Issue 41, item 13: the names ".", "" and "   " all saved to saves/untitled.toml (and "a/b",
// "a\\b", "a_b" all to saves/a_b.toml), so a later save silently replaced another world's.
TEST(WorldStore, DifferentWorldNamesNeverShareADefaultSave) {
    const char* names[] = {".",   "",     "   ", "untitled", "..",  "....",
                           "a/b", "a\\b", "a_b", "x\ny",     "x y", "/"};
    std::set<fs::path> paths;
    for (const char* name : names) {
        const fs::path p = game::defaultSavePath(name);
        EXPECT_TRUE(paths.insert(p).second) << "'" << name << "' shares " << p;
        EXPECT_EQ(p.parent_path(), fs::path("saves")) << p;
    }
    EXPECT_EQ(game::defaultSavePath("a_b"),
              fs::path("saves/a_b.toml"));  // a name that is safe stays as it is
}

// Issue 41, item 13 for worlds without a name: both were named "untitled" and saved to
// saves/untitled.toml, one over the other. A world without a name takes its file's.
TEST(WorldStore, WorldsWithoutANameInDifferentFilesNeverShareADefaultSave) {
    const char* kUnnamed = "[world]\nsize = [8, 8, 8]\n";
    auto meadow = engine::scene::loadSceneText(kUnnamed, "worlds/meadow.toml");
    auto cave = engine::scene::loadSceneText(kUnnamed, "elsewhere/cave.toml");
    ASSERT_TRUE(meadow.ok() && cave.ok());
    EXPECT_EQ(meadow->name, "meadow");
    EXPECT_NE(game::defaultSavePath(meadow->name), game::defaultSavePath(cave->name));
}

// Issue 41, item 11 for saves: a scene file name near NAME_MAX (255 bytes) left no room for the
// payload's ".N.vdb" or an object's ".object-HASH.vdb"; their stem is shortened instead.
TEST(WorldStore, ASaveWithAFileNameNearTheLimitWorks) {
    TempDir dir;
    const fs::path file = dir.path() / (std::string(250, 'w') + ".toml");
    Scene scene = makeScene(7);
    ASSERT_TRUE(game::makeWorldStore()->save(scene, file).ok());
    auto result = game::makeWorldStore()->save(scene, file);
    ASSERT_TRUE(result.ok()) << result.error().message;
    auto loaded = game::makeWorldStore()->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    expectSameWorld(scene, *loaded, "a long name");
    EXPECT_EQ(countFiles(dir.path(), ".vdb"), 1u);
}
