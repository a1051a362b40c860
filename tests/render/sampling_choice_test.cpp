// --sampling auto's choice (render/sampling_choice.h) from the facts of small generated floors:
// few lights, lights within a cell or two, or more lights per cell than it has entries draw by
// power; many lights spread over many of ReGIR's cells, a few in each, draw from its grid;
// explicit settings are never changed.
#include "render/sampling_choice.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lighting/emitter_list.h"
#include "scene/scene_file.h"

using engine::lighting::EmitterList;
using engine::lighting::LightingSettings;
using engine::render::autoChoosesRegir;
using engine::render::resolveSampling;
using engine::render::SamplingFacts;
using engine::render::samplingFacts;

namespace {

// A 256 x 32 x 256 floor with single-voxel lamps every `spacing` voxels over a centred square of
// `footprint` voxels.
SamplingFacts floorFacts(int spacing, int footprint) {
    const std::string text = fmt::format(R"([world]
name = "floor"
size = [256, 32, 256]
[[material]]
name = "floor"
albedo = [0.5, 0.5, 0.5]
[[material]]
name = "lamp"
emission = [1.0, 1.0, 1.0]
strength = 1.0
[[generator]]
type = "box"
min = [0, 0, 0]
max = [256, 1, 256]
material = "floor"
[[generator]]
type = "scattered_lights"
spacing = {}
size = [1, 1, 1]
margin = {}
light = "lamp"
)",
                                         spacing, (256 - footprint) / 2);
    auto scene = engine::scene::loadSceneText(text, "floor.toml");
    EXPECT_TRUE(scene.ok()) << scene.error().message;
    EmitterList list;
    list.rebuild(*scene);
    return samplingFacts(list, scene->grid.sizeInVoxels(), LightingSettings{}.regir);
}

}  // namespace

TEST(SamplingChoice, ManyLightsOverManyCellsDrawFromTheGrid) {
    const SamplingFacts f = floorFacts(8, 256);  // 32 x 32 lamps over the floor
    EXPECT_EQ(f.emitters, 1024u);
    EXPECT_EQ(f.regirCell, 16.0);                        // 256 x 32 x 256 / 16^3 = 512 cells
    EXPECT_NEAR(f.spread, 256.0 / std::sqrt(6.0), 4.0);  // uniform over a square: edge / sqrt 6
    EXPECT_EQ(f.perOccupiedCell, 4.0);  // 2 x 2 lamps over each 16 x 16 cell of the floor
    EXPECT_TRUE(autoChoosesRegir(f));
}

TEST(SamplingChoice, MoreLightsPerCellThanEntriesDrawByPower) {
    const SamplingFacts f = floorFacts(2, 256);  // 128 x 128 lamps, 64 in each floor cell
    EXPECT_EQ(f.emitters, 16384u);
    EXPECT_GT(f.spread, 2.0 * f.regirCell);
    EXPECT_EQ(f.perOccupiedCell, 64.0);
    EXPECT_FALSE(autoChoosesRegir(f));
}

TEST(SamplingChoice, LightsWithinACellOrTwoDrawByPower) {
    const SamplingFacts f = floorFacts(2, 32);  // 16 x 16 lamps in a 32-voxel square
    EXPECT_EQ(f.emitters, 256u);
    EXPECT_LT(f.spread, 2.0 * f.regirCell);
    EXPECT_FALSE(autoChoosesRegir(f));
}

TEST(SamplingChoice, FewLightsDrawByPowerHoweverFarApart) {
    const SamplingFacts f = floorFacts(64, 256);  // 4 x 4 lamps over the floor
    EXPECT_EQ(f.emitters, 16u);
    EXPECT_GT(f.spread, 2.0 * f.regirCell);
    EXPECT_FALSE(autoChoosesRegir(f));
}

TEST(SamplingChoice, ResolvingChangesOnlyAuto) {
    LightingSettings autoDefault;
    const LightingSettings toRegir = resolveSampling(autoDefault, true);
    EXPECT_FALSE(toRegir.autoSampling);
    EXPECT_EQ(toRegir.regir.enabled, 1u);
    EXPECT_TRUE(toRegir.byPower);
    const LightingSettings toPower = resolveSampling(autoDefault, false);
    EXPECT_FALSE(toPower.autoSampling);
    EXPECT_EQ(toPower.regir.enabled, 0u);
    EXPECT_TRUE(toPower.byPower);

    LightingSettings power = autoDefault;
    power.autoSampling = false;
    EXPECT_EQ(resolveSampling(power, true), power);
    LightingSettings uniform = autoDefault;
    uniform.byPower = false;  // set in code without naming the sampling: uniform stays uniform
    EXPECT_EQ(resolveSampling(uniform, true).regir.enabled, 0u);
    EXPECT_FALSE(resolveSampling(uniform, true).byPower);
}
