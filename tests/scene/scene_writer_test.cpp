// The one scene writer: every world in worlds/ loads, writes and loads back to the same scene
// (scene/scene_equality.h), writing is a fixed point (the text of a written-back scene is the
// text written), and every table — [indirect], [[object]] with both rotation forms, [path] with
// every event type — survives, with names quoted and floats exact.
#include <filesystem>
#include <gtest/gtest.h>
#include <vector>

#include "scene/scene_equality.h"
#include "scene/scene_file.h"
#include "scene/scene_lighting.h"
#include "world/flythrough.h"

using namespace engine::world;
using namespace engine::scene;
using engine::scene::test::sceneDifference;
namespace fs = std::filesystem;

namespace {

// Every scene file in worlds/, so a new world is covered without touching this test.
std::vector<fs::path> shippedWorlds() {
    std::vector<fs::path> out;
    for (const fs::directory_entry& e :
         fs::directory_iterator(fs::path(VOX_SOURCE_DIR) / "worlds")) {
        if (e.path().extension() == ".toml") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Relative payload paths in the text resolve against the original's folder.
std::string besideOriginal(const fs::path& world) {
    return (world.parent_path() / "written_back.toml").string();
}

}  // namespace

TEST(SceneWriter, EveryShippedWorldLoadsWritesAndLoadsBackTheSame) {
    std::vector<fs::path> worlds = shippedWorlds();
    ASSERT_GE(worlds.size(), 9u);
    for (const fs::path& world : worlds) {
        auto scene = loadSceneFile(world);
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        std::string text = sceneText(*scene);
        auto back = loadSceneText(text, besideOriginal(world));
        ASSERT_TRUE(back.ok()) << world << ": " << back.error().message << "\n" << text;
        EXPECT_EQ(sceneDifference(*scene, *back), "") << world << "\n" << text;
    }
}

TEST(SceneWriter, WritingIsAFixedPoint) {
    for (const fs::path& world : shippedWorlds()) {
        auto scene = loadSceneFile(world);
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        std::string first = sceneText(*scene);
        EXPECT_EQ(sceneText(*scene), first) << world;
        auto back = loadSceneText(first, besideOriginal(world));
        ASSERT_TRUE(back.ok()) << world << ": " << back.error().message;
        EXPECT_EQ(sceneText(*back), first) << world;
    }
}

TEST(SceneWriter, KeepsIndirectObjectsAndEveryPathEvent) {
    const char* kScene = R"([world]
name = "all tables"
size = [32, 32, 32]

[[material]]
name = "stone"
albedo = [0.5, 0.5, 0.5]

[[material]]
name = "lamp"
albedo = [1.0, 1.0, 1.0]
emission = [1.0, 0.9, 0.7]
strength = 6.0

[[generator]]
type = "box"
min = [0, 0, 0]
max = [32, 2, 32]
material = "stone"

[[object]]
name = "spinner"
size = [4, 2, 6]
loop = false

[[object.generator]]
type = "sphere"
center = [2, 1, 3]
radius = 1.7
material = "lamp"

[[object.key]]
time = 0.0
position = [10, 6.5, 10]
rotation = [30, -10.25, 5]

[[object.key]]
time = 1.5
position = [20.1, 6, 10]
axis = [0.3, 1, 0.2]
angle = 33.3

[[object.key]]
time = 2.0
position = [20, 6, 20]

[indirect]
mode = "cache"
directions = 64
rays = 8
bounces = 2
alpha = 0.05
fade = 0.7
neighbourhood = 3
max_ray = 123.5
filter = false
budget_mb = 12.5

[path]
fps = 24
duration = 3.0

[[path.key]]
time = 0.0
position = [-5, 20, -5]
target = [16, 2, 16]
fov = 50

[[path.key]]
time = 1.1
position = [40, 25, 0.3]
target = [16, 2, 16]

[[path.event]]
time = 0.5
type = "box"
min = [1, 2, 3]
max = [4, 5, 6]
material = "empty"

[[path.event]]
time = 0.6
type = "sphere"
center = [8.5, 3, 8]
radius = 2.25
material = "stone"

[[path.event]]
time = 0.7
type = "voxel"
at = [9, 9, 9]
material = "lamp"

[[path.event]]
time = 0.8
type = "light"
material = "lamp"
on = false

[[path.event]]
time = 0.9
type = "light"
material = "lamp"
on = true
min = [0, 0, 0]
max = [16, 16, 16]

[[path.event]]
time = 1.0
type = "dynamic"
object = "spinner"
)";
    auto scene = loadSceneText(kScene, "all.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    ASSERT_TRUE(scene->path);
    EXPECT_EQ(scene->path->timeline.events().size(), 6u);
    auto lighting = engine::scene::lightingFor(&*scene, {});
    ASSERT_TRUE(lighting.ok()) << lighting.error().message;
    EXPECT_EQ(lighting->indirect, engine::lighting::Indirect::Cache);
    EXPECT_EQ(lighting->cache.maxRayLength, 123.5f);
    std::string text = sceneText(*scene);
    auto back = loadSceneText(text, "back.toml");
    ASSERT_TRUE(back.ok()) << back.error().message << "\n" << text;
    EXPECT_EQ(sceneDifference(*scene, *back), "") << text;
    EXPECT_EQ(sceneText(*back), text);
    // The settings as given, not their defaults, and the object's model rebuilt from its generator.
    auto backLighting = engine::scene::lightingFor(&*back, {});
    ASSERT_TRUE(backLighting.ok()) << backLighting.error().message;
    EXPECT_EQ(backLighting->cache.directions, 64u);
    EXPECT_FALSE(backLighting->cache.filter);
    EXPECT_EQ(backLighting->cache, lighting->cache);
    ASSERT_EQ(back->objects.size(), 1u);
    EXPECT_GT(back->objects[0].model->solidVoxels(), 0u);
}

TEST(SceneWriter, LeavesOutIndirectAndPathWhenTheSceneHasNone) {
    Scene scene;
    std::string text = sceneText(scene);
    EXPECT_EQ(text.find("[indirect]"), std::string::npos) << text;
    EXPECT_EQ(text.find("[path]"), std::string::npos) << text;
}

TEST(SceneWriter, QuotesNamesAndKeepsFloatsExact) {
    Scene scene;
    scene.name = "a \"quoted\" \\ name\twith tab";
    Material m;
    m.name = "odd \"name\"";
    m.albedo = {0.1f, 1.0f / 3.0f, 0.7f};
    m.emissionColor = {1.0f, 0.5f, 0.25f};
    m.emissionStrength = 3.0f;
    scene.palette.add(m);
    scene.cameras.push_back({"c", {1e-3f, 123456.7f, -0.1f}, {2.0f, 2.0f, 2.0f}, 60.0f});
    scene.voxelSize = 0.1f;
    std::string text = sceneText(scene, {.headerComment = "two\nlines"});
    EXPECT_EQ(text.rfind("# two\n# lines\n", 0), 0u) << text;
    auto back = loadSceneText(text, "t.toml");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(sceneDifference(scene, *back), "") << text;
}
