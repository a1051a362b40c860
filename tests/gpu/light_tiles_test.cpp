// Presampled light tiles (render/light_tiles/): the tiles hold emitters drawn by power with their
// true probabilities, and resampling from them converges to the same image as alias-table draws.
#include "render/light_tiles/light_tiles.h"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <map>

#include "gpu/command_list.h"
#include "gpu/gpu_test_setup.h"
#include "gpu/sample_stats.h"
#include "shared/light_tiles.h"
#include "world/world_edits.h"

using namespace engine::world;
using namespace gpu_testing;

namespace {

constexpr MaterialId kWhite = 1, kLamp = 2, kDim = 3;

// A floor and wall under one bright 8^3 brick light and three dim voxel lamps (powers far apart,
// so a wrong probability shows in the counts).
Scene lampScene() {
    Scene scene =
        paletteScene({48, 32, 48},
                     {Material{"white", glm::vec3(0.75f)},
                      Material{"lamp", glm::vec3(0.8f), glm::vec3(1.0f, 0.85f, 0.6f), 4.0f},
                      Material{"dim", glm::vec3(0.8f), glm::vec3(0.3f, 0.5f, 1.0f), 2.0f}},
                     true);
    fillBox(scene.grid, Box{{0, 0, 0}, {48, 2, 48}}, kWhite);
    fillBox(scene.grid, Box{{0, 2, 40}, {48, 32, 48}}, kWhite);
    fillBox(scene.grid, Box{{24, 16, 16}, {32, 24, 24}}, kLamp);
    scene.grid.set({8, 3, 8}, kDim);
    scene.grid.set({40, 6, 12}, kDim);
    scene.grid.set({12, 10, 30}, kDim);
    scene.cameras.push_back(
        CameraPreset{"front", {24.0f, 28.0f, -16.0f}, {24.0f, 4.0f, 24.0f}, 60.0f});
    scene.grid.clearDirty();
    return scene;
}

std::vector<shared::LightTileSample> readTiles(const Renderer& r) {
    const engine::gpu::Buffer& tiles = r.lightTiles().samples();
    engine::gpu::Buffer readback(context(), engine::gpu::BufferKind::Readback, tiles.size(),
                                 "test.tiles");
    engine::gpu::CommandList cmd(context());
    cmd.begin();
    cmd.copyBuffer(tiles, readback, {{0, 0, tiles.size()}});
    cmd.barrier();
    cmd.submitAndWait();
    std::vector<shared::LightTileSample> out(tiles.size() / sizeof(shared::LightTileSample));
    std::memcpy(out.data(), readback.mapped(), tiles.size());
    return out;
}

}  // namespace

class LightTiles : public GpuTest {};

// Every entry is a live emitter with its own data and probability power / total power, and each
// emitter appears as often as that probability says (within 5 binomial standard deviations).
TEST_F(LightTiles, EntriesAreEmittersDrawnByPower) {
    Scene scene = lampScene();
    Renderer r(context());
    LightingSettings l;
    l.restir.lightTiles = 1;
    r.render(scene, scene.camera(), frame(16), l);
    const std::vector<shared::LightTileSample> tiles = readTiles(r);
    ASSERT_EQ(tiles.size(), std::size_t(shared::LIGHT_TILE_COUNT) * shared::LIGHT_TILE_SIZE);
    const engine::lighting::EmitterList& list = r.emitters();
    ASSERT_EQ(list.aliveCount(), 4u);
    std::map<std::uint32_t, int> counts;
    for (const shared::LightTileSample& t : tiles) {
        const std::uint32_t slot = t.info.z;
        ASSERT_LT(slot, list.slots().size());
        const shared::GpuEmitter& e = list.slots()[slot];
        ASSERT_TRUE(e.info.w & shared::EMITTER_FLAG_ALIVE);
        EXPECT_EQ(t.minCorner, e.minCorner);
        EXPECT_EQ(t.info.x, e.info.x);
        EXPECT_EQ(t.info.y, e.info.y);
        EXPECT_EQ(glm::vec3(t.radiance), glm::vec3(e.radiance));
        EXPECT_NEAR(t.radiance.w, e.radiance.w / list.totalPower(), 1e-6);
        ++counts[slot];
    }
    const double n = double(tiles.size());
    for (std::uint32_t slot : list.aliveSlots()) {
        const double p = list.slots()[slot].radiance.w / list.totalPower();
        const double sigma = std::sqrt(n * p * (1.0 - p));
        std::printf("slot %u: probability %.5f, %d of %.0f entries (expected %.1f +- %.1f)\n", slot,
                    p, counts[slot], n, n * p, sigma);
        EXPECT_NEAR(counts[slot], n * p, 5.0 * sigma + 1.0);
    }
}

// RIS (no reuse, so frames are independent) with candidates from the tiles and from the alias
// table: the mean image brightness over frames agrees within 4 standard errors.
TEST_F(LightTiles, ResamplingFromTilesMatchesAliasDraws) {
    Scene scene = lampScene();
    auto frameMeans = [&](bool tiles) {
        Renderer r(context());
        LightingSettings l;
        l.method = Method::Ris;
        l.restir.candidates = 4;
        l.restir.lightTiles = tiles ? 1u : 0u;
        std::vector<double> means;
        for (int f = 0; f < 48; ++f) {
            r.render(scene, scene.camera(), frame(32), l);
            means.push_back(meanLuminance(r.readback().radiance));
        }
        return meanOfMeans(means);
    };
    const MeanAndError alias = frameMeans(false), tiles = frameMeans(true);
    const double sigma = std::sqrt(alias.standardError * alias.standardError +
                                   tiles.standardError * tiles.standardError);
    std::printf("mean brightness: alias draws %.5f +- %.5f, light tiles %.5f +- %.5f\n", alias.mean,
                alias.standardError, tiles.mean, tiles.standardError);
    ASSERT_GT(alias.mean, 1e-3);
    EXPECT_LT(std::abs(tiles.mean - alias.mean), 4.0 * sigma + 1e-4 * alias.mean);
}
