#include "scene/scene_file.h"

#include <filesystem>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>

#include "world/generators.h"
#include "world/world_info.h"

using namespace engine::world;
using namespace engine::scene;

namespace {

std::string errorOf(const std::string& text) {
    auto scene = loadSceneText(text, "test.toml");
    EXPECT_FALSE(scene.ok()) << "expected an error for:\n" << text;
    return scene.ok() ? std::string() : scene.error().message;
}

const char* kMinimal = R"([world]
size = [16, 16, 16]
[[material]]
name = "stone"
)";

}  // namespace

TEST(SceneFile, EveryShippedWorldLoads) {
    int count = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(VOX_SOURCE_DIR) / "worlds")) {
        if (entry.path().extension() != ".toml") continue;
        auto scene = loadSceneFile(entry.path());
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        EXPECT_GT(scene->grid.solidVoxels(), 0u) << entry.path();
        EXPECT_FALSE(scene->cameras.empty()) << entry.path();
        EXPECT_TRUE(scene->grid.dirtyBricks().empty())
            << "a freshly loaded world has nothing pending";
        ++count;
    }
    EXPECT_GE(count, 3);
}

TEST(SceneFile, ErrorsNameTheFileAndLine) {
    std::string e = errorOf(std::string(kMinimal) + "\n[[generator]]\ntype = \"terain\"\n");
    EXPECT_EQ(e,
              "test.toml:7: unknown generator 'terain' (known: terrain, box, sphere, cornell, "
              "buildings, lamps, "
              "mountain, scattered_lights, text, menger, apartment, bridge, vdb, vox, store)");
    // Saves from before .vdb payloads are refused by name, not as a typo.
    e = errorOf(std::string(kMinimal) +
                "\n[[generator]]\ntype = \"bricks\"\nfile = \"old.1.bricks\"\n");
    EXPECT_EQ(e,
              "test.toml:7: generator 'bricks' (the .bricks payload of older vox play saves) is no "
              "longer "
              "supported; saves are .vdb now (docs/SANDBOX.md, Saves)");
    e = errorOf(std::string(kMinimal) + "albdo = [1, 1, 1]\n");
    EXPECT_EQ(e, "test.toml:5: unknown key 'albdo'");
    e = errorOf(
        std::string(kMinimal) +
        "[[generator]]\ntype = \"box\"\nmin = [0,0,0]\nmax = [4,4,4]\nmaterial = \"gold\"\n");
    EXPECT_EQ(e, "test.toml:9: unknown material 'gold'");
    e = errorOf("[world]\nsize = [16, 16\n");
    EXPECT_NE(e.find("test.toml:2:"), std::string::npos) << e;
    e = errorOf("[[material]]\nname = \"x\"\n");
    EXPECT_NE(e.find("missing [world]"), std::string::npos) << e;
}

TEST(SceneFile, AbsurdSizesAreRefused) {
    std::string e = errorOf("[world]\nsize = [32768, 32768, 32768]\n");
    EXPECT_NE(e.find("test.toml:2: world size 32768x32768x32768 needs"), std::string::npos) << e;
    e = errorOf("[world]\nsize = [0, 16, 16]\n");
    EXPECT_NE(e.find("test.toml:2: 'size' x must be positive, not 0; allowed: 1..32768 voxels"),
              std::string::npos)
        << e;
    e = errorOf("[world]\nsize = [1.5, 16, 16]\n");
    EXPECT_NE(e.find("'size' x must be a whole number in 1..32768 voxels, not 1.5"),
              std::string::npos)
        << e;
    // A whole number that is too large says so (it is not "not whole").
    e = errorOf("[world]\nsize = [16, 4294967291, 16]\n");
    EXPECT_NE(e.find("test.toml:2: 'size' y is too large (max 32768), not 4294967291"),
              std::string::npos)
        << e;
    e = errorOf("[world]\nsize = [16, -5, 16]\n");
    EXPECT_NE(e.find("test.toml:2: 'size' y must be positive, not -5"), std::string::npos) << e;
}

TEST(SceneFile, CornellBoxHasTheThesisLight) {
    auto scene = loadSceneFile(std::filesystem::path(VOX_SOURCE_DIR) / "worlds/cornell.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->emissiveVoxels(), 131072u);  // 256 bricks of 8^3
    MaterialId light = *scene->palette.find("light");
    int lightCells = 0;
    for (std::uint32_t c : scene->grid.denseCells())
        lightCells += c == (shared::CELL_HOMOGENEOUS | light);
    EXPECT_EQ(lightCells, 256) << "each emissive brick is a homogeneous cell (a brick light)";
}

// Memory follows content: doubling the air above a terrain adds only region-table entries (the
// top grid is paged by region) and super cells.
TEST(SceneFile, EmptyAirCostsOnlyRegionTableEntries) {
    TerrainParams p;
    p.top = 1;
    p.soil = 2;
    p.rock = 3;
    p.baseHeight = 96;
    p.amplitude = 64;
    p.wavelength = 300;
    p.octaves = 5;
    BrickGrid low({1024, 256, 1024}), high({1024, 512, 1024});
    generateTerrain(low, p);
    generateTerrain(high, p);
    EXPECT_EQ(low.liveBricks(), high.liveBricks());
    EXPECT_EQ(low.memory().brickPoolBytes, high.memory().brickPoolBytes);
    EXPECT_EQ(high.topGrid().livePages(), low.topGrid().livePages());
    const std::size_t extraRegions = high.topGrid().table().size() - low.topGrid().table().size();
    EXPECT_EQ(extraRegions, 8u * 2u * 8u);
    // A table entry and its changed flag per region.
    EXPECT_EQ(high.memory().topGridBytes - low.memory().topGridBytes,
              extraRegions * (sizeof(std::uint32_t) + 1u));
    // The pool holds only non-uniform bricks: far fewer than the cells the terrain touches.
    EXPECT_LT(low.liveBricks(), low.cellCount() / 10);
    for (std::uint32_t c : low.denseCells()) {
        if (BrickGrid::cellIsBrick(c)) {
            ASSERT_FALSE(isUniform(low.brickVoxels(BrickGrid::cellBrick(c))));
        }
    }
    Scene scene;
    for (const char* name : {"grass", "dirt", "stone"}) (void)scene.palette.add(Material{name});
    scene.grid = std::move(low);
    WorldInfo info = describeWorld(scene);
    EXPECT_EQ(info.topGridBytes, scene.grid.memory().topGridBytes);
    EXPECT_LT(info.topGridBytes, 128u * 32u * 128u * 4u * 2u)
        << "pages (cells and their marks) of the regions the terrain occupies";
    EXPECT_EQ(info.brickPoolBytes, info.bricks * (1024u + 80u));
}

namespace {
const char* kObject = R"([world]
size = [32, 32, 32]
[[material]]
name = "stone"
[[object]]
name = "cube"
size = [4, 4, 4]
[[object.generator]]
type = "box"
min = [0, 0, 0]
max = [4, 2, 4]
material = "stone"
[[object.key]]
time = 0.0
position = [10, 10, 10]
[[object.key]]
time = 2.0
position = [20, 10, 10]
rotation = [90, 0, 0]
)";
}  // namespace

TEST(SceneFile, ObjectsBuildTheirModelsAndPaths) {
    auto scene = loadSceneText(kObject, "test.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->grid.solidVoxels(), 0u) << "object generators write the model, not the world";
    ASSERT_EQ(scene->objects.size(), 1u);
    const DynamicObject& o = scene->objects[0];
    EXPECT_EQ(o.name, "cube");
    EXPECT_EQ(o.modelSize, glm::ivec3(4));
    EXPECT_EQ(o.model->solidVoxels(), 32u);
    EXPECT_TRUE(o.path.loop());
    EXPECT_EQ(o.path.at(1.0).position, glm::dvec3(15, 10, 10));
    EXPECT_EQ(o.path.at(2.0).position, glm::dvec3(10, 10, 10)) << "the loop wraps at the last key";
    // Loaded at time 0: the dynamic grid holds the cube's lower half at 8..11 x 8..9 x 8..11.
    ASSERT_TRUE(scene->dynamic.present());
    EXPECT_EQ(scene->dynamic.get({8, 8, 8}), 1);
    EXPECT_EQ(scene->dynamic.get({11, 9, 11}), 1);
    EXPECT_EQ(scene->dynamic.get({8, 10, 8}), kEmpty);
}

TEST(SceneFile, ObjectErrorsNameTheLine) {
    std::string base = kObject;
    auto with = [&](const std::string& from, const std::string& to) {
        std::string s = base;
        s.replace(s.find(from), from.size(), to);
        return errorOf(s);
    };
    EXPECT_EQ(with("time = 2.0", "time = 0.0"),
              "test.toml:17: key times must increase (0 follows 0)");
    EXPECT_EQ(with("type = \"box\"", "type = \"cube\""),
              "test.toml:9: unknown generator 'cube' (known: terrain, box, sphere, cornell, "
              "buildings, lamps, "
              "mountain, scattered_lights, text, menger, apartment, bridge, vdb, vox, store)");
    EXPECT_EQ(with("size = [4, 4, 4]", "size = [4, 0, 4]"),
              "test.toml:7: 'size' y must be positive, not 0; allowed: 1..256 voxels");
    EXPECT_EQ(with("rotation = [90, 0, 0]", "rotation = [90, 0, 0]\nangle = 4"),
              "test.toml:16: key: give 'rotation' or 'axis' and 'angle', not both");
    EXPECT_EQ(with("position = [20, 10, 10]", "positon = [20, 10, 10]"),
              "test.toml:16: missing 'position'");
    EXPECT_EQ(with("name = \"cube\"", "name = \"cube\"\nspeed = 3"),
              "test.toml:7: unknown key 'speed'");
    EXPECT_EQ(with("max = [4, 2, 4]", "max = [0, 0, 0]"),
              "test.toml:8: object 'cube': its generators leave the model empty");
    std::string e = errorOf(base.substr(0, base.find("[[object.key]]")));
    EXPECT_EQ(e, "test.toml:5: object 'cube' needs at least one [[object.key]]");
    e = errorOf(base.substr(0, base.find("[[object.key]]\ntime = 2.0")));
    EXPECT_EQ(e, "test.toml:13: a looping path needs at least two keys");
}

// [sky] sky_light is the `sky` lighting knob: read through it (a bad value names the key and
// the choices), written back, and merged under the command line's --sky.
TEST(SceneFile, SkyLightKeyIsTheSkyKnob) {
    const std::string text = std::string(kMinimal) + "[sky]\nsky_light = \"dvf\"\n";
    auto scene = loadSceneText(text, "test.toml");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene->sky.lightMode, "dvf");
    auto again = loadSceneText(sceneText(*scene), "again.toml");
    ASSERT_TRUE(again.ok()) << again.error().message;
    EXPECT_EQ(again->sky.lightMode, "dvf");
    const std::string error = errorOf(std::string(kMinimal) + "[sky]\nsky_light = \"bright\"\n");
    EXPECT_NE(error.find("sky_light"), std::string::npos) << error;
    EXPECT_NE(error.find("dvf"), std::string::npos) << error;
}

TEST(SceneFile, TextFromTheFileIsEscapedInMessagesAndNamesArePrintable) {
    // Keys and values are the file's text. A message quoting them shows control characters
    // escaped -- one line, nothing for a terminal to act on -- and a name (world, material,
    // camera, object) is printable text, so whatever shows it later shows what the file says.
    auto clean = [](const std::string& m) {
        for (char c : m)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                return ::testing::AssertionFailure() << "control byte " << int(c) << " in: " << m;
        return ::testing::AssertionSuccess();
    };
    const std::string unknownKey =
        errorOf("[world]\nsize = [16, 16, 16]\n\"\\u001B]2;pwned\\u0007\\u001B[31m\" = 1\n");
    EXPECT_TRUE(clean(unknownKey));
    EXPECT_NE(unknownKey.find("unknown key '\\u001B]2;pwned\\u0007\\u001B[31m'"), std::string::npos)
        << unknownKey;
    const std::string unknownType =
        errorOf(std::string(kMinimal) + "[[generator]]\ntype = \"ter\\nrain\\u0000\"\n");
    EXPECT_TRUE(clean(unknownType));
    EXPECT_NE(unknownType.find("ter\\nrain\\u0000"), std::string::npos) << unknownType;
    for (const char* name : {"two\\nlines", "nul\\u0000cut", "\\u001B[2J", "c1 \\u009B31m"}) {
        const std::string world =
            errorOf(fmt::format("[world]\nname = \"{}\"\nsize = [16, 16, 16]\n", name));
        EXPECT_TRUE(clean(world));
        EXPECT_NE(world.find("test.toml:2: 'name' must be printable text"), std::string::npos)
            << world;
        EXPECT_NE(world.find(name), std::string::npos) << world;
    }
    // A TOML syntax error quoting a raw control character.
    EXPECT_TRUE(clean(errorOf("[world]\nsize = [16, 16, 16]\nname = \"a\x1b[31mb\"\n")));
}
