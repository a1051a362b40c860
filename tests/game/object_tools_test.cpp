// The sandbox's object tool: a model loads from a scene file, .vox or .vdb (big ones refused),
// is placed on the face under the crosshair, moves by whole voxels, turns about Y, records keys
// at the current time, loses its path, is deleted; every command undoes and redoes exactly; and
// a save gives the objects back (model voxels, path keys, loop).
#include "game/object_tools.h"

#include <GLFW/glfw3.h>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

#include "game/input.h"
#include "game/world_store.h"
#include "io/vdb_export.h"
#include "io/vox_export.h"
#include "scene/scene_equality.h"
#include "scene/scene_file.h"

using namespace engine::world;
namespace fs = std::filesystem;

namespace {

class TempDir {
public:
    TempDir() {
        char pattern[] = "/tmp/vox_objects_XXXXXX";
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

// A 3 x 3 x 2 crate with a lamp on one corner: 13 voxels, lying off the world's origin
// (tests/game/crate.toml, also the scripted run's model).
std::string crateWorld() {
    std::ifstream in(VOX_GAME_TEST_DIR "/crate.toml");
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_FALSE(text.str().empty()) << "cannot read " VOX_GAME_TEST_DIR "/crate.toml";
    return text.str();
}

fs::path writeText(const fs::path& file, const std::string& text) {
    std::ofstream(file) << text;
    return file;
}

game::ObjectModel crateModel(const TempDir& dir) {
    auto model = game::loadObjectModel(writeText(dir.path() / "crate.toml", crateWorld()));
    EXPECT_TRUE(model.ok()) << (model.ok() ? "" : model.error().message);
    return std::move(*model);
}

// A 64 x 32 x 64 world with a stone floor 4 voxels thick.
Scene floorScene() {
    Scene scene;
    scene.name = "floor";
    Material stone;
    stone.name = "stone";
    stone.albedo = glm::vec3(0.5f);
    scene.palette.add(stone);
    scene.grid = BrickGrid({64, 32, 64});
    for (int z = 0; z < 64; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 64; ++x) scene.grid.set({x, y, z}, 1);
    scene.grid.clearDirty();
    return scene;
}

game::Pick lookDownAt(const Scene& scene, float x, float z) {
    return game::pick(scene.grid, {x, 30.0f, z}, {0.0f, -1.0f, 0.0f});
}

// The world voxels an object covers now, as "x y z material" lines (from the dynamic grid).
std::string dynamicVoxels(const Scene& scene) {
    std::string out;
    if (!scene.dynamic.present()) return out;
    const glm::ivec3 size = scene.dynamic.grid.sizeInVoxels();
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::ivec3 w = glm::ivec3(x, y, z) + scene.dynamic.origin;
                if (MaterialId m = scene.dynamic.get(w); m != kEmpty)
                    out += fmt::format("{} {} {} {}\n", w.x, w.y, w.z, m);
            }
    return out;
}

std::size_t lines(const std::string& s) {
    return std::size_t(std::count(s.begin(), s.end(), '\n'));
}

// Everything an object command may change, in words: names, models, keys, loop.
std::string describeObjects(const Scene& scene) {
    std::string out;
    for (const DynamicObject& o : scene.objects) {
        out += fmt::format("{} size {} {} {} voxels {} loop {}\n", o.name, o.modelSize.x,
                           o.modelSize.y, o.modelSize.z, o.model->solidVoxels(), o.path.loop());
        for (const ObjectKey& k : o.path.keys())
            out += fmt::format("  key {} at {} {} {} yaw {}\n", k.time, k.position.x, k.position.y,
                               k.position.z, k.angles.x);
    }
    return out;
}

}  // namespace

TEST(ObjectTools, LoadsAModelFromASceneFileAVoxAndAVdbCroppedToItsVoxels) {
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    EXPECT_EQ(crate.name, "crate");
    EXPECT_EQ(crate.size, glm::ivec3(3, 3, 2));
    EXPECT_EQ(crate.solidVoxels, 13u);
    EXPECT_EQ(crate.palette[crate.voxels.get({0, 0, 0})].name, "crate");
    EXPECT_EQ(crate.palette[crate.voxels.get({2, 2, 1})].name, "lamp");
    EXPECT_EQ(crate.voxels.get({0, 2, 0}), kEmpty);

    auto world = engine::scene::loadSceneFile(dir.path() / "crate.toml");
    ASSERT_TRUE(world.ok()) << world.error().message;
    ASSERT_TRUE(engine::io::exportVox(*world, dir.path() / "crate.vox").ok());
    ASSERT_TRUE(engine::io::exportVdb(*world, dir.path() / "crate.vdb").ok());
    for (const char* name : {"crate.vox", "crate.vdb"}) {
        auto model = game::loadObjectModel(dir.path() / name);
        ASSERT_TRUE(model.ok()) << name << ": " << model.error().message;
        EXPECT_EQ(model->size, glm::ivec3(3, 3, 2)) << name;
        EXPECT_EQ(model->solidVoxels, 13u) << name;
    }
}

TEST(ObjectTools, RefusesModelsBeyondTheCapOrEmpty) {
    TempDir dir;
    std::string big = crateWorld();
    big +=
        "[[generator]]\ntype = \"box\"\nmin = [0, 8, 0]\nmax = [32, 24, 32]\nmaterial = "
        "\"crate\"\n";  // 16384 more
    auto refused = game::loadObjectModel(writeText(dir.path() / "big.toml", big));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("16397 solid voxels; a model holds at most 16384"),
              std::string::npos)
        << refused.error().message;

    std::string empty = crateWorld();
    empty = empty.substr(0, empty.find("[[generator]]"));
    auto none = game::loadObjectModel(writeText(dir.path() / "empty.toml", empty));
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("no solid voxels"), std::string::npos)
        << none.error().message;
}

TEST(ObjectTools, PlacesTheModelOnTheFaceUnderTheCrosshair) {
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    game::UndoHistory undo(64 << 20);
    game::Pick target = lookDownAt(scene, 32.5f, 32.5f);  // floor top (32, 3, 32), face +Y
    ASSERT_TRUE(target.hit);
    game::ObjectResult r = game::placeObject(scene, undo, crate, target, 1.0);
    ASSERT_TRUE(r.changed) << r.message;
    ASSERT_EQ(scene.objects.size(), 1u);
    const DynamicObject& o = scene.objects[0];
    EXPECT_EQ(o.name, "crate_1");
    EXPECT_EQ(o.path.keys().size(), 1u);
    EXPECT_FALSE(o.path.loop());
    // Lowest corner on the voxel above the floor, centred across the face: (31, 4, 31).
    EXPECT_EQ(o.path.keys()[0].position, glm::dvec3(32.5, 5.5, 32.0));
    // The world's palette took the model's materials by name; the voxels are the model's, exactly.
    auto crateId = scene.palette.find("crate"), lampId = scene.palette.find("lamp");
    ASSERT_TRUE(crateId && lampId);
    const std::string voxels = dynamicVoxels(scene);
    EXPECT_EQ(lines(voxels), 13u) << voxels;
    EXPECT_EQ(scene.dynamic.get({31, 4, 31}), *crateId);
    EXPECT_EQ(scene.dynamic.get({33, 5, 32}), *crateId);
    EXPECT_EQ(scene.dynamic.get({33, 6, 32}), *lampId);
    EXPECT_EQ(scene.dynamic.get({31, 6, 31}), kEmpty);

    // The sky places nothing and says why.
    game::Pick sky = game::pick(scene.grid, {32.0f, 30.0f, 32.0f}, {0.0f, 1.0f, 0.0f});
    game::ObjectResult none = game::placeObject(scene, undo, crate, sky, 1.0);
    EXPECT_FALSE(none.changed);
    EXPECT_NE(none.message.find("sky"), std::string::npos) << none.message;
    EXPECT_EQ(scene.objects.size(), 1u);
}

TEST(ObjectTools, PicksTheObjectUnderTheCrosshair) {
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    game::UndoHistory undo(64 << 20);
    game::placeObject(scene, undo, crate, lookDownAt(scene, 10.5f, 10.5f), 0.0);
    game::placeObject(scene, undo, crate, lookDownAt(scene, 40.5f, 40.5f), 0.0);
    EXPECT_EQ(game::pickObject(scene, {40.5f, 30.0f, 40.5f}, {0.0f, -1.0f, 0.0f}),
              std::optional<std::size_t>(1));
    EXPECT_EQ(game::pickObject(scene, {10.5f, 30.0f, 10.5f}, {0.0f, -1.0f, 0.0f}),
              std::optional<std::size_t>(0));
    EXPECT_EQ(game::pickObject(scene, {20.5f, 30.0f, 20.5f}, {0.0f, -1.0f, 0.0f}),
              std::nullopt);  // the floor
}

TEST(ObjectTools, MovesByWholeVoxelsAndTurnsAboutYShowingTheModelExactly) {
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    game::UndoHistory undo(64 << 20);
    game::placeObject(scene, undo, crate, lookDownAt(scene, 32.5f, 32.5f), 0.0);
    const std::string placed = dynamicVoxels(scene);

    // A static object: the move changes its one key.
    ASSERT_TRUE(game::moveObject(scene, undo, 0, {2, 0, -1}, 5.0).changed);
    EXPECT_EQ(scene.objects[0].path.keys().size(), 1u);
    EXPECT_EQ(scene.objects[0].path.keys()[0].position, glm::dvec3(34.5, 5.5, 31.0));
    EXPECT_EQ(scene.dynamic.get({33, 4, 30}), *scene.palette.find("crate"));
    EXPECT_EQ(lines(dynamicVoxels(scene)), 13u);
    ASSERT_TRUE(game::moveObject(scene, undo, 0, {-2, 0, 1}, 5.0).changed);
    EXPECT_EQ(dynamicVoxels(scene), placed);

    // A quarter turn: the box's x and z extents swap, snapped to whole voxels, every voxel kept.
    ASSERT_TRUE(game::turnObject(scene, undo, 0, 90.0, 5.0).changed);
    const ObjectKey& k = scene.objects[0].path.keys()[0];
    EXPECT_EQ(k.angles.x, 90.0);
    EXPECT_EQ(k.given, ObjectKey::Given::YawPitchRoll);
    const Box b = scene.dynamic.instances[0].bounds;
    EXPECT_EQ(b.max - b.min, glm::ivec3(2, 3, 3));
    EXPECT_EQ(lines(dynamicVoxels(scene)), 13u);
    // A turn back, and four quarter turns, come back to the placed voxels (no half-voxel drift).
    ASSERT_TRUE(game::turnObject(scene, undo, 0, -90.0, 5.0).changed);
    EXPECT_EQ(dynamicVoxels(scene), placed);
    for (int i = 0; i < 4; ++i) ASSERT_TRUE(game::turnObject(scene, undo, 0, 90.0, 5.0).changed);
    EXPECT_EQ(scene.objects[0].path.keys()[0].angles.x, 0.0);
    EXPECT_EQ(dynamicVoxels(scene), placed);

    // Free turns in 5 degree steps keep the yaw as a scene file writes it.
    ASSERT_TRUE(game::turnObject(scene, undo, 0, -game::kFreeTurnDegrees, 5.0).changed);
    EXPECT_EQ(scene.objects[0].path.keys()[0].angles.x, -5.0);
}

TEST(ObjectTools, KeysRecordThePoseShownAtTheirTime) {
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    game::UndoHistory undo(64 << 20);
    game::placeObject(scene, undo, crate, lookDownAt(scene, 20.5f, 20.5f), 1.0);
    const glm::dvec3 p0 = scene.objects[0].path.keys()[0].position;

    // K on a static object starts a looping path; a move with a path keys the current time.
    ASSERT_TRUE(game::setObjectKey(scene, undo, 0, 2.0).changed);
    ASSERT_EQ(scene.objects[0].path.keys().size(), 2u);
    EXPECT_TRUE(scene.objects[0].path.loop());
    EXPECT_EQ(scene.objects[0].path.keys()[1].position, p0);
    ASSERT_TRUE(game::moveObject(scene, undo, 0, {8, 0, 0}, 4.0).changed);
    const auto& keys = scene.objects[0].path.keys();
    ASSERT_EQ(keys.size(), 3u);
    EXPECT_EQ(keys[2].time, 4.0);
    EXPECT_EQ(keys[2].position, p0 + glm::dvec3(8, 0, 0));
    // Moving again within the key tolerance replaces that key.
    ASSERT_TRUE(game::moveObject(scene, undo, 0, {0, 0, 2}, 4.0 + game::kKeyTolerance / 2).changed);
    ASSERT_EQ(scene.objects[0].path.keys().size(), 3u);
    EXPECT_EQ(scene.objects[0].path.keys()[2].position, p0 + glm::dvec3(8, 0, 2));

    // A key between keys takes the pose shown at its time (on whole voxels here), and the path
    // then passes through it at that time.
    ASSERT_TRUE(game::toggleObjectLoop(scene, undo, 0, 3.0).changed);
    EXPECT_FALSE(scene.objects[0].path.loop());
    const RigidTransform shown = scene.objects[0].poseAt(3.0);
    const glm::dvec3 half = glm::dvec3(crate.size) * 0.5;
    ASSERT_TRUE(game::setObjectKey(scene, undo, 0, 3.0).changed);
    ASSERT_EQ(scene.objects[0].path.keys().size(), 4u);
    const ObjectKey& mid = scene.objects[0].path.keys()[2];
    EXPECT_EQ(mid.time, 3.0);
    EXPECT_EQ(mid.position,
              glm::ceil(shown.position - half - 0.5) + half);  // halves round down unturned
    EXPECT_EQ(scene.objects[0].poseAt(3.0).position, mid.position);

    // Clearing the path leaves the object static where it is shown.
    ASSERT_TRUE(game::clearObjectPath(scene, undo, 0, 4.0).changed);
    ASSERT_EQ(scene.objects[0].path.keys().size(), 1u);
    EXPECT_EQ(scene.objects[0].path.keys()[0].position, p0 + glm::dvec3(8, 0, 2));
    EXPECT_FALSE(game::toggleObjectLoop(scene, undo, 0, 4.0).changed);  // no path to loop
}

TEST(ObjectTools, EveryCommandUndoesAndRedoesExactly) {
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    game::UndoHistory undo(64 << 20);
    std::vector<std::pair<std::string, std::string>> states{
        {describeObjects(scene), dynamicVoxels(scene)}};
    auto step = [&](game::ObjectResult r) {
        ASSERT_TRUE(r.changed) << r.message;
        states.emplace_back(describeObjects(scene), dynamicVoxels(scene));
    };
    step(game::placeObject(scene, undo, crate, lookDownAt(scene, 20.5f, 20.5f), 1.0));
    step(game::placeObject(scene, undo, crate, lookDownAt(scene, 40.5f, 20.5f), 1.5));
    step(game::moveObject(scene, undo, 0, {1, 2, 3}, 2.0));
    step(game::turnObject(scene, undo, 1, 90.0, 2.0));
    step(game::setObjectKey(scene, undo, 0, 3.0));
    step(game::moveObject(scene, undo, 0, {5, 0, 0}, 4.0));
    step(game::toggleObjectLoop(scene, undo, 0, 4.0));
    step(game::clearObjectPath(scene, undo, 0, 5.0));
    step(game::deleteObject(scene, undo, 0, 5.0));
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].name, "crate_2");

    for (std::size_t i = states.size() - 1; i > 0; --i) {
        ASSERT_FALSE(undo.undo(scene.grid, scene.objects).empty());
        game::refreshObjects(scene, 0.0);
        EXPECT_EQ(describeObjects(scene), states[i - 1].first) << "after undoing step " << i;
        // Poses are at time 0 here, the states were taken at their own times: compare models only
        // for the static first steps.
        if (i <= 2) {
            EXPECT_EQ(dynamicVoxels(scene), states[i - 1].second) << "after undoing step " << i;
        }
    }
    EXPECT_TRUE(undo.undo(scene.grid, scene.objects).empty());
    for (std::size_t i = 1; i < states.size(); ++i) {
        ASSERT_FALSE(undo.redo(scene.grid, scene.objects).empty());
        EXPECT_EQ(describeObjects(scene), states[i].first) << "after redoing step " << i;
    }
    EXPECT_TRUE(undo.redo(scene.grid, scene.objects).empty());
}

TEST(ObjectTools, PlacedObjectsSaveAndLoadEqual) {
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    game::UndoHistory undo(64 << 20);
    game::placeObject(scene, undo, crate, lookDownAt(scene, 20.5f, 20.5f), 1.0);
    game::turnObject(scene, undo, 0, 90.0, 1.0);
    game::setObjectKey(scene, undo, 0, 2.0);
    game::moveObject(scene, undo, 0, {6, 0, 0}, 3.25);
    game::turnObject(scene, undo, 0, -5.0, 4.5);
    game::placeObject(scene, undo, crate, lookDownAt(scene, 40.5f, 40.5f), 2.0);
    ASSERT_EQ(scene.objects[0].path.keys().size(), 4u);

    auto store = game::makeWorldStore();
    const fs::path file = dir.path() / "saves" / "objects.toml";
    ASSERT_TRUE(store->save(scene, file).ok());
    auto loaded = store->load(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    // Everything a scene file says, objects included (model voxels, path keys, loop).
    EXPECT_EQ(engine::scene::test::sceneDifference(scene, *loaded), "");
    EXPECT_EQ(describeObjects(*loaded), describeObjects(scene));
    // Both objects have the same model: one payload of its own beside the world's.
    std::vector<std::string> payloads;
    for (const auto& e : fs::directory_iterator(file.parent_path()))
        if (e.path().filename().string().starts_with("objects.object-"))
            payloads.push_back(e.path().filename().string());
    ASSERT_EQ(payloads.size(), 1u);
    // Saving the loaded scene again names the same payload; deleting the objects removes it.
    ASSERT_TRUE(store->save(*loaded, file).ok());
    EXPECT_TRUE(fs::exists(file.parent_path() / payloads[0]));
    game::deleteObject(*loaded, undo, 1, 0.0);
    game::deleteObject(*loaded, undo, 0, 0.0);
    ASSERT_TRUE(store->save(*loaded, file).ok());
    EXPECT_FALSE(fs::exists(file.parent_path() / payloads[0]));
    auto empty = store->load(file);
    ASSERT_TRUE(empty.ok()) << empty.error().message;
    EXPECT_TRUE(empty->objects.empty());
}

TEST(ObjectTools, DraggingTheSelectedObjectFollowsTheCrosshairAndUndoesInOneStep) {
    TempDir dir;
    Scene scene = floorScene();
    game::UndoHistory undo(64 << 20);
    game::ObjectTools tools;
    tools.active = true;
    tools.models.push_back(crateModel(dir));
    game::InputState input;
    // One frame looking straight down at (x, z), the left button going down/up or held as it is.
    auto frame = [&](std::optional<bool> left, float x, float z) {
        input.beginFrame();
        if (left)
            input.apply({game::InputEventType::MouseButton, GLFW_MOUSE_BUTTON_LEFT, *left, {}});
        const glm::vec3 origin(x, 30.0f, z), down(0.0f, -1.0f, 0.0f);
        return tools.handle(input, true, game::pick(scene.grid, origin, down), origin, down, scene,
                            undo, 1.0);
    };
    ASSERT_TRUE(
        frame(true, 20.5f, 20.5f).changed);  // places crate_1 (lowest corner 19 4 19), selected
    frame(false, 20.5f, 20.5f);
    ASSERT_EQ(tools.selected, std::optional<std::size_t>(0));
    const std::string placed = dynamicVoxels(scene);

    // Pressed on the selected object: a drag, not a second placement.
    EXPECT_NE(frame(true, 20.5f, 20.5f).message.find("dragging crate_1"), std::string::npos);
    frame(std::nullopt, 25.5f, 20.5f);
    frame(std::nullopt, 30.5f, 24.5f);
    game::ObjectResult dropped = frame(false, 30.5f, 24.5f);
    ASSERT_TRUE(dropped.changed) << dropped.message;
    EXPECT_NE(dropped.message.find("drag crate_1 by 10 0 4"), std::string::npos) << dropped.message;
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].path.keys().size(), 1u);
    EXPECT_EQ(scene.dynamic.get({29, 4, 23}), *scene.palette.find("crate"));
    EXPECT_EQ(lines(dynamicVoxels(scene)), 13u);
    // The whole drag is one step.
    EXPECT_EQ(undo.stats().undoSteps, 2u);
    ASSERT_FALSE(undo.undo(scene.grid, scene.objects).empty());
    game::refreshObjects(scene, 1.0);
    EXPECT_EQ(dynamicVoxels(scene), placed);
}

namespace {

// The process's resident memory (VmRSS in /proc/self/status).
std::size_t residentBytes() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::size_t(std::stoull(line.substr(6))) << 10;
    ADD_FAILURE() << "no VmRSS in /proc/self/status";
    return 0;
}

}  // namespace

TEST(ObjectTools, FourHundredNudgesKeepMemoryFlat) {
    // Each move is an undo step holding the object as it was; the model is shared with the scene,
    // so a step costs its path keys, not a copy of the model's brick pool (a whole page).
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    game::UndoHistory undo(256u << 20);  // vox play's default: the budget drops nothing here
    ASSERT_TRUE(
        game::placeObject(scene, undo, crate, lookDownAt(scene, 20.5f, 20.5f), 0.0).changed);
    const std::size_t bound = 64u << 20;
    const std::size_t start = residentBytes();
    for (int i = 0; i < 400; ++i) {
        ASSERT_TRUE(game::moveObject(scene, undo, 0, {i % 2 == 0 ? 1 : -1, 0, 0}, 0.0).changed);
        // Stop at once past the bound: the leak would take gigabytes by the end.
        ASSERT_LE(residentBytes(), start + bound)
            << "after " << i + 1 << " nudges the process grew by "
            << (residentBytes() - start) / double(1 << 20) << " MiB";
    }
    EXPECT_EQ(undo.stats().undoSteps, 401u);
    EXPECT_EQ(undo.stats().droppedSteps, 0u);
    // Undo and redo all of it: still flat.
    while (undo.canUndo()) undo.undo(scene.grid, scene.objects);
    while (undo.canRedo()) undo.redo(scene.grid, scene.objects);
    EXPECT_LE(residentBytes(), start + bound);
}

TEST(ObjectTools, TheUndoBudgetCountsWhatAStepHoldsAndDropsOldSteps) {
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    // The model's grid holds one page of bricks however few it uses: what a deleted object's
    // step keeps alive.
    const std::uint64_t page = BrickGrid::poolBytesFor(1);
    game::UndoHistory undo(256u << 20);
    game::placeObject(scene, undo, crate, lookDownAt(scene, 20.5f, 20.5f), 0.0);
    game::deleteObject(scene, undo, 0, 0.0);
    EXPECT_GE(undo.stats().bytes, page) << "a deleted crate's step holds its model";
    undo.undo(scene.grid, scene.objects);  // back in the scene: the step holds nothing of it
    EXPECT_LT(undo.stats().bytes, page / 16);

    // A budget of 64 KiB: nudges share the model, so a few hundred bytes each; the oldest go.
    game::UndoHistory small(64u << 10);
    game::placeObject(scene, small, crate, lookDownAt(scene, 40.5f, 40.5f), 0.0);
    for (int i = 0; i < 400; ++i)
        game::moveObject(scene, small, 1, {i % 2 == 0 ? 1 : -1, 0, 0}, 0.0);
    const game::UndoStats s = small.stats();
    EXPECT_LE(s.bytes, s.maxBytes);
    EXPECT_GT(s.droppedSteps, 0u);
    EXPECT_GT(s.undoSteps, 50u) << "a nudge step costs far less than the budget / 50";
    EXPECT_EQ(s.undoSteps + s.droppedSteps, 401u);
}

TEST(ObjectTools, AStepTooLargeToKeepEndsTheHistoryAndFreesWhatItHeld) {
    // Under a budget smaller than a model's page, deleting an object cannot be undone: its step
    // would hold the model. The moves before it cannot be undone either (they name the object
    // by its place in the list, and it is gone), so they go too, and the model with them.
    TempDir dir;
    game::ObjectModel crate = crateModel(dir);
    Scene scene = floorScene();
    game::UndoHistory undo(1u << 20);  // vox play --undo-mb 1, as the soak runs
    game::placeObject(scene, undo, crate, lookDownAt(scene, 20.5f, 20.5f), 0.0);
    const std::weak_ptr<const BrickGrid> model = scene.objects[0].model;
    for (int i = 0; i < 3; ++i) game::moveObject(scene, undo, 0, {1, 0, 0}, 0.0);
    EXPECT_EQ(undo.stats().undoSteps, 4u);
    game::deleteObject(scene, undo, 0, 0.0);
    EXPECT_FALSE(undo.canUndo());
    EXPECT_EQ(undo.stats().bytes, 0u);
    EXPECT_TRUE(model.expired()) << "the deleted crate's model is still held (" << model.use_count()
                                 << " holders)";
}
