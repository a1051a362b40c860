// The generators behind the thesis scenes: text, Menger sponge, scattered lights, mountain,
// apartment blocks and bridges, each on a tiny grid with counts worked out by hand.
#include <gtest/gtest.h>
#include <string>

#include "scene/scene_file.h"
#include "world/apartment_generator.h"
#include "world/bridge_generator.h"
#include "world/generators.h"
#include "world/menger_generator.h"
#include "world/mountain_generator.h"
#include "world/scattered_lights_generator.h"
#include "world/text_generator.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace engine::scene;

namespace {

constexpr MaterialId kStone = 1, kLight = 2, kOther = 3;

std::uint64_t countMaterial(const BrickGrid& grid, MaterialId m) {
    std::uint64_t n = 0;
    const glm::ivec3 size = grid.sizeInVoxels();
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) n += grid.get({x, y, z}) == m;
    return n;
}

int emptyNeighbours(const BrickGrid& grid, glm::ivec3 p) {
    int n = 0;
    for (glm::ivec3 d : {glm::ivec3(1, 0, 0), glm::ivec3(-1, 0, 0), glm::ivec3(0, 1, 0),
                         glm::ivec3(0, -1, 0), glm::ivec3(0, 0, 1), glm::ivec3(0, 0, -1)})
        n += grid.get(p + d) == kEmpty;
    return n;
}

std::string errorOf(const std::string& generator) {
    std::string text =
        "[world]\nsize = [32, 32, 32]\n[[material]]\nname = \"stone\"\n[[generator]]\n" + generator;
    auto scene = loadSceneText(text, "test.toml");
    EXPECT_FALSE(scene.ok()) << "expected an error for:\n" << generator;
    return scene.ok() ? std::string() : scene.error().message;
}

}  // namespace

TEST(TextGenerator, WritesEveryFontPixelScaledAndExtruded) {
    BrickGrid grid({64, 32, 16});
    TextParams p;
    p.text = "HI 7";
    p.origin = {1, 1, 8};
    p.scale = 2;
    p.depth = 3;
    p.material = kLight;
    ASSERT_EQ(validateTextParams(p), "");
    // H 17 + I 11 + 7 11 font pixels, each 2 x 2 x 3 voxels.
    EXPECT_EQ(textVoxelCount(p), (17 + 11 + 11) * 12);
    generateText(grid, p);
    EXPECT_EQ(grid.solidVoxels(), std::uint64_t(textVoxelCount(p)));
}

TEST(TextGenerator, GlyphsStandUprightAlongRight) {
    BrickGrid grid({32, 32, 32});
    TextParams p;
    p.text = "L";
    p.origin = {2, 2, 5};
    p.material = kLight;
    generateText(grid, p);
    for (int y = 2; y < 9; ++y) EXPECT_EQ(grid.get({2, y, 5}), kLight) << "the L's bar, y " << y;
    for (int x = 2; x < 7; ++x)
        EXPECT_EQ(grid.get({x, 2, 5}), kLight) << "the L's foot on the baseline, x " << x;
    EXPECT_EQ(grid.get({3, 8, 5}), kEmpty) << "nothing right of the bar's top";
    // Depth goes away from the reader: the face looks along cross(right, up) = +z, layers go -z.
    p.depth = 2;
    p.origin = {12, 2, 5};
    generateText(grid, p);
    EXPECT_EQ(grid.get({12, 2, 4}), kLight);
    EXPECT_EQ(grid.get({12, 2, 6}), kEmpty);
}

// A letter set into a wall shows only its face: each voxel has exactly one empty neighbour.
TEST(TextGenerator, LettersSetIntoAWallAreEnclosedButForTheirFace) {
    BrickGrid grid({32, 32, 40});
    fillBox(grid, Box{{0, 0, 0}, {8, 32, 40}}, kStone);  // a wall whose inner face is x = 8
    TextParams p;
    p.text = "VOX";
    p.origin = {7, 10, 30};
    p.right = {0, 0, -1};  // read from inside (looking towards -x), the line runs towards -z
    p.up = {0, 1, 0};
    p.material = kLight;
    generateText(grid, p);
    std::uint64_t letters = 0;
    for (int z = 0; z < 40; ++z)
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 8; ++x) {
                if (grid.get({x, y, z}) != kLight) continue;
                ++letters;
                EXPECT_EQ(x, 7) << "one voxel deep, in the surface layer";
                EXPECT_EQ(emptyNeighbours(grid, {x, y, z}), 1) << "at " << y << ", " << z;
            }
    EXPECT_EQ(letters, std::uint64_t(textVoxelCount(p)));
}

TEST(TextGenerator, SceneFileErrorsNameTheLine) {
    EXPECT_EQ(
        errorOf("type = \"text\"\ntext = \"50%\"\norigin = [0, 0, 0]\nmaterial = \"stone\"\n"),
        "test.toml:5: text: no glyph for '%' (the font has A-Z, 0-9, . - + :)");
    std::string e = errorOf(
        "type = \"text\"\ntext = \"A\"\norigin = [0, 0, 0]\nright = [1, 1, 0]\nmaterial = "
        "\"stone\"\n");
    EXPECT_NE(e.find("test.toml:5: text: 'right' and 'up' must be perpendicular"),
              std::string::npos)
        << e;
    e = errorOf(
        "type = \"text\"\ntext = \"A\"\norigin = [0, 0, 0]\nup = [1, 0, 0]\nmaterial = "
        "\"stone\"\n");
    EXPECT_NE(e.find("perpendicular"), std::string::npos) << e;
    e = errorOf(
        "type = \"text\"\ntext = \"A\"\norigin = [0, 0, 0]\nmaterial = \"stone\"\nsize = 3\n");
    EXPECT_EQ(e, "test.toml:10: unknown key 'size'");
}

TEST(MengerGenerator, HasTwentyToTheLevelCubes) {
    BrickGrid grid({64, 64, 64});
    MengerParams p;
    p.origin = {4, 3, 2};
    p.level = 3;
    p.scale = 2;
    p.material = kStone;
    EXPECT_EQ(mengerEdge(p), 54);
    EXPECT_EQ(mengerVoxelCount(p), 8000 * 8);
    generateMenger(grid, p);
    EXPECT_EQ(grid.solidVoxels(), 64000u);
    EXPECT_EQ(grid.get(p.origin), kStone) << "corners stay";
    EXPECT_EQ(grid.get(p.origin + 27), kEmpty) << "the centre is hollow";
    EXPECT_EQ(grid.get(p.origin + glm::ivec3(0, 27, 27)), kEmpty)
        << "a tunnel runs through the faces";
    EXPECT_EQ(grid.get(p.origin + glm::ivec3(7, 7, 0)), kEmpty) << "second-level tunnel";
    EXPECT_EQ(grid.get(p.origin + glm::ivec3(2, 2, 0)), kEmpty) << "third-level tunnel";
    EXPECT_EQ(grid.get(p.origin + glm::ivec3(1, 1, 0)), kStone);
}

TEST(ScatteredLightsGenerator, OneLightPerCellStandingOnTheGround) {
    BrickGrid grid({64, 32, 64});
    fillBox(grid, Box{{0, 0, 0}, {64, 4, 64}}, kStone);
    fillBox(grid, Box{{0, 4, 0}, {16, 9, 16}}, kStone);  // a raised corner
    ScatteredLightsParams p;
    p.spacing = 8;
    p.size = {1, 3, 1};
    p.light = kLight;
    EXPECT_EQ(generateScatteredLights(grid, p), 64);
    EXPECT_EQ(countMaterial(grid, kLight), 64u * 3u) << "no two lights overlap";
    for (int z = 0; z < 64; ++z)
        for (int x = 0; x < 64; ++x) {
            int ground = (x < 16 && z < 16) ? 9 : 4;
            MaterialId bottom = grid.get({x, ground, z});
            if (bottom != kLight) continue;
            EXPECT_EQ(grid.get({x, ground - 1, z}), kStone) << x << ", " << z;
            EXPECT_EQ(grid.get({x, ground + 2, z}), kLight);
            EXPECT_EQ(grid.get({x, ground + 3, z}), kEmpty);
        }
    // Seeded: the same seed places the same lights, another seed elsewhere.
    BrickGrid again({64, 32, 64}), other({64, 32, 64});
    fillBox(again, Box{{0, 0, 0}, {64, 4, 64}}, kStone);
    fillBox(again, Box{{0, 4, 0}, {16, 9, 16}}, kStone);
    fillBox(other, Box{{0, 0, 0}, {64, 4, 64}}, kStone);
    fillBox(other, Box{{0, 4, 0}, {16, 9, 16}}, kStone);
    generateScatteredLights(again, p);
    p.seed += 1;
    generateScatteredLights(other, p);
    EXPECT_TRUE(grid == again);
    EXPECT_FALSE(grid == other);
}

TEST(ScatteredLightsGenerator, SkipsLightsThatWouldLeaveTheWorld) {
    BrickGrid grid({16, 8, 16});
    fillBox(grid, Box{{0, 0, 0}, {16, 6, 16}}, kStone);
    ScatteredLightsParams p;
    p.light = kLight;
    EXPECT_EQ(generateScatteredLights(grid, p), 0);
    EXPECT_EQ(countMaterial(grid, kLight), 0u);
}

TEST(MountainGenerator, ColumnsFollowTheHeightFunction) {
    MountainParams p;
    p.materials.top = kStone;
    p.materials.soil = kStone;
    p.materials.rock = kStone;
    p.materials.snow = kLight;
    p.materials.snowLine = 50;
    p.peak = {64, 64};
    p.peakHeight = 90;
    p.baseHeight = 10;
    p.radius = 70;
    p.terrace = 2;
    BrickGrid grid({128, 112, 128});
    generateMountain(grid, p);
    for (int z = 0; z < 128; z += 9)
        for (int x = 0; x < 128; x += 7) {
            int h = mountainHeight(p, x, z);
            ASSERT_EQ(groundHeight(grid, x, z), h) << x << ", " << z;
            EXPECT_EQ(h % 2, 0) << "terraces of 2";
            EXPECT_EQ(grid.get({x, h - 1, z}), h - 1 >= 50 ? kLight : kStone)
                << "snow above the snow line";
        }
    // Ridges scale the rise by 1 +- 0.35, hills add +-8: the summit is at least 10 - 8 + 0.65 * 80.
    EXPECT_GT(mountainHeight(p, 64, 64), 50);
    EXPECT_EQ(grid.get({64, mountainHeight(p, 64, 64) - 1, 64}), kLight) << "a snowy summit";
    EXPECT_LT(mountainHeight(p, 0, 0), 30);
}

TEST(BridgeGenerator, LightsLineBothEdgesBesideTheRailing) {
    BrickGrid grid({64, 16, 16});
    BridgeParams p;
    p.min = {0, 6, 4};
    p.max = {48, 7, 12};  // runs along x, 8 wide
    p.lightSpacing = 8;
    p.deck = kStone;
    p.railing = kOther;
    p.light = kLight;
    generateBridge(grid, p);
    EXPECT_EQ(bridgeLightCount(p), 12);  // at x = 4, 12, ..., 44 on both sides
    EXPECT_EQ(countMaterial(grid, kLight), 12u);
    for (int x = 4; x < 48; x += 8) {
        EXPECT_EQ(grid.get({x, 7, 5}), kLight) << x;
        EXPECT_EQ(grid.get({x, 7, 10}), kLight) << x;
        EXPECT_EQ(grid.get({x, 9, 4}), kOther) << "the top rail over the light";
    }
    EXPECT_EQ(grid.get({0, 7, 4}), kOther) << "a railing post";
    EXPECT_EQ(grid.get({1, 7, 4}), kEmpty) << "between posts";
    EXPECT_EQ(grid.get({20, 6, 8}), kStone) << "the deck";
    EXPECT_EQ(grid.get({20, 7, 8}), kEmpty) << "the walkway is clear";
}

TEST(ApartmentGenerator, LitWindowsAreTheOnlyLightsAndCountAsWorkedOut) {
    ApartmentParams p;
    p.min = {8, 40, 8};
    p.size = {32, 17, 24};
    p.baseDepth = 10;
    p.wall = kStone;
    p.slab = kStone;
    p.railing = kStone;
    p.base = kOther;
    p.windowLights = {kLight};
    p.lit = 1.0f;
    BrickGrid grid({64, 80, 48});
    generateApartment(grid, p);
    // 2 storeys; windows 3 wide every 6: 5 along the 32-long facades, 3 along the 24-long ones;
    // 2 * (5 + 3) per storey, 3 x 4 voxels each.
    EXPECT_EQ(countMaterial(grid, kLight), 2u * 2u * (5u + 3u) * 12u);
    EXPECT_GT(countMaterial(grid, kOther), 0u) << "rock underneath";
    EXPECT_EQ(grid.get({20, 39, 20}), kOther);

    p.lit = 0.0f;
    BrickGrid dark({64, 80, 48});
    generateApartment(dark, p);
    EXPECT_EQ(countMaterial(dark, kLight), 0u);
    p.cornerLight = kLight;
    BrickGrid corners({64, 80, 48});
    generateApartment(corners, p);
    EXPECT_EQ(countMaterial(corners, kLight), 4u * 17u) << "four neon strips, full height";
}

TEST(ApartmentGenerator, SeedChangesTheFacadesNotTheShell) {
    ApartmentParams p;
    p.min = {8, 8, 8};
    p.size = {32, 25, 32};
    p.wall = kStone;
    p.slab = kStone;
    p.windowLights = {kLight, kOther};
    BrickGrid a({48, 48, 48}), b({48, 48, 48}), c({48, 48, 48});
    generateApartment(a, p);
    generateApartment(b, p);
    p.seed = 99;
    generateApartment(c, p);
    EXPECT_TRUE(a == b);
    EXPECT_FALSE(a == c);
    EXPECT_EQ(a.get({8, 8, 8}), c.get({8, 8, 8}));
}

TEST(SceneGenerators, ParseErrorsNameTheLine) {
    EXPECT_EQ(errorOf("type = \"menger\"\nlevel = 9\nmaterial = \"stone\"\n"),
              "test.toml:7: 'level' is too large (max 6), not 9; allowed: 0..6");
    EXPECT_EQ(
        errorOf("type = \"scattered_lights\"\nspacing = 4\nsize = [5, 1, 1]\nlight = \"stone\"\n"),
        "test.toml:8: 'size' must be at least 1, at most 'spacing' across and 256 high");
    EXPECT_EQ(
        errorOf("type = \"apartment\"\nmin = [0, 0, 0]\nsize = [16, 16, 16]\nwall = \"stone\"\n"
                "slab = \"stone\"\nwindows = [\"stone\", \"glas\"]\n"),
        "test.toml:11: unknown material 'glas'");
    EXPECT_EQ(errorOf("type = \"bridge\"\nmin = [0, 0, 0]\nmax = [8, 0, 8]\ndeck = \"stone\"\n"),
              "test.toml:8: 'max' must exceed 'min' on every axis");
    EXPECT_EQ(errorOf("type = \"mountain\"\ntop = \"stone\"\nsoil = \"stone\"\nrock = "
                      "\"stone\"\nridges = 2.0\n"),
              "test.toml:10: 'ridges' is too large (max 1), not 2; allowed: [0, 1]");
}
