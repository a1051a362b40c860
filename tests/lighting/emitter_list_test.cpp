#include "lighting/emitter_list.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <tuple>

#include "core/hash.h"
#include "lighting/alias_table.h"
#include "world/world_edits.h"

using namespace engine::world;
using engine::lighting::EmitterList;
using engine::lighting::EmitterSettings;

namespace {

Scene sceneWithLight(glm::ivec3 size) {
    Scene scene;
    scene.grid = BrickGrid(size);
    (void)scene.palette.add(Material{"stone", glm::vec3(0.5f)});
    (void)scene.palette.add(Material{"lamp", glm::vec3(1.0f), glm::vec3(1.0f, 0.8f, 0.6f), 4.0f});
    (void)scene.palette.add(Material{"blue", glm::vec3(1.0f), glm::vec3(0.2f, 0.3f, 1.0f), 2.0f});
    return scene;
}

using Key =
    std::tuple<int, int, int, int, std::uint32_t, std::uint32_t>;  // corner, size, faces, material

std::map<Key, std::uint32_t> emitterSet(const EmitterList& list) {
    std::map<Key, std::uint32_t> out;
    for (std::uint32_t slot : list.aliveSlots()) {
        const shared::GpuEmitter& e = list.slots()[slot];
        out[{e.minCorner.x, e.minCorner.y, e.minCorner.z, e.minCorner.w, e.info.x, e.info.z}] =
            slot;
    }
    return out;
}

}  // namespace

TEST(EmitterList, EnclosedEmissiveVoxelsAreNotEmitters) {
    Scene scene = sceneWithLight({32, 32, 32});
    fillBox(scene.grid, Box{{10, 10, 10}, {13, 13, 13}}, 1);  // stone shell
    scene.grid.set({11, 11, 11}, 2);                          // lamp inside it
    scene.grid.set({20, 20, 20}, 2);                          // a free lamp
    scene.grid.set({20, 21, 20}, 1);                          // stone on top of it
    EmitterList list;
    list.rebuild(scene);
    ASSERT_EQ(list.aliveCount(), 1u);
    const shared::GpuEmitter& e = list.slots()[list.aliveSlots()[0]];
    EXPECT_EQ(glm::ivec3(e.minCorner), glm::ivec3(20, 20, 20));
    EXPECT_EQ(e.minCorner.w, 1);
    EXPECT_EQ(e.info.x, 0b110111u) << "every face but +Y is exposed";
}

TEST(EmitterList, UniformEmissiveCellIsOneBrickLight) {
    Scene scene = sceneWithLight({64, 64, 64});
    fillBox(scene.grid, Box{{8, 16, 8}, {24, 24, 16}}, 2);  // two aligned emissive cells
    EmitterList list;
    list.rebuild(scene);
    EXPECT_EQ(list.aliveCount(), 2u);
    for (std::uint32_t slot : list.aliveSlots()) {
        EXPECT_EQ(list.slots()[slot].minCorner.w, 8);
        // The shared side between the two cells is not exposed: 5 faces each.
        EXPECT_EQ(std::popcount(list.slots()[slot].info.x), 5);
    }
    EmitterList voxels(EmitterSettings{false});
    voxels.rebuild(scene);
    // Brick lights off: the exposed surface voxels of the 16x8x8 block.
    EXPECT_EQ(voxels.aliveCount(), 16u * 8u * 8u - 14u * 6u * 6u);
    // Same total power either way: the same exposed area.
    EXPECT_NEAR(voxels.totalPower(), list.totalPower(), 1e-6 * list.totalPower());
}

TEST(EmitterList, IncrementalUpdateMatchesFullRebuild) {
    for (bool brickLights : {true, false}) {
        Scene scene = sceneWithLight({64, 48, 64});
        fillBox(scene.grid, Box{{0, 0, 0}, {64, 8, 64}}, 1);
        fillBox(scene.grid, Box{{16, 8, 16}, {32, 16, 32}}, 2);
        engine::Rng rng(5);
        for (int i = 0; i < 300; ++i)
            scene.grid.set({rng.uniformInt(0, 63), rng.uniformInt(8, 30), rng.uniformInt(0, 63)},
                           MaterialId(rng.uniformInt(1, 3)));
        EmitterList incremental(EmitterSettings{brickLights});
        incremental.rebuild(scene);
        scene.grid.clearDirty();
        for (int round = 0; round < 20; ++round) {
            auto before = emitterSet(incremental);
            for (int i = 0; i < 15; ++i) {
                glm::ivec3 p{rng.uniformInt(0, 63), rng.uniformInt(0, 30), rng.uniformInt(0, 63)};
                scene.grid.set(p, MaterialId(rng.uniformInt(0, 3)));
            }
            if (round % 5 == 0)
                fillBox(scene.grid, Box{{40, 8, 40}, {48, 16, 48}}, MaterialId(round % 2 ? 2 : 0));
            auto stats = incremental.update(scene);
            EXPECT_FALSE(stats.full);
            EXPECT_LE(stats.cellsScanned, 7u * 30u);
            scene.grid.clearDirty();
            EmitterList full(EmitterSettings{brickLights});
            full.rebuild(scene);
            auto now = emitterSet(incremental);
            ASSERT_EQ(now.size(), emitterSet(full).size()) << "round " << round;
            for (const auto& [key, slot] : emitterSet(full))
                ASSERT_TRUE(now.count(key)) << "round " << round;
            // Emitters untouched by the edits kept their slots.
            int kept = 0;
            for (const auto& [key, slot] : before) kept += now.count(key) && now.at(key) == slot;
            EXPECT_GT(kept, int(before.size()) / 2);
        }
    }
}

TEST(EmitterList, RemovedSlotsChangeGeneration) {
    Scene scene = sceneWithLight({32, 32, 32});
    scene.grid.set({5, 5, 5}, 2);
    EmitterList list;
    list.rebuild(scene);
    ASSERT_EQ(list.aliveCount(), 1u);
    std::uint32_t slot = list.aliveSlots()[0];
    std::uint32_t generation = list.slots()[slot].info.y;
    scene.grid.clearDirty();
    scene.grid.set({5, 5, 5}, 0);
    list.update(scene);
    EXPECT_EQ(list.aliveCount(), 0u);
    EXPECT_NE(list.slots()[slot].info.y, generation);
    EXPECT_EQ(list.slots()[slot].info.w & shared::EMITTER_FLAG_ALIVE, 0u);
    scene.grid.clearDirty();
    scene.grid.set({9, 9, 9}, 3);  // reuses the slot with yet another generation
    list.update(scene);
    ASSERT_EQ(list.aliveCount(), 1u);
    EXPECT_EQ(list.aliveSlots()[0], slot);
    EXPECT_NE(list.slots()[slot].info.y, generation);
}

TEST(AliasTable, SamplesInProportionToWeights) {
    std::vector<std::uint32_t> slots{7, 3, 9, 4};
    std::vector<double> weights{1.0, 0.0, 5.0, 2.0};
    auto table = engine::lighting::buildAliasTable(slots, weights);
    ASSERT_EQ(table.size(), 4u);
    // Exact probabilities from the table.
    std::map<std::uint32_t, double> p;
    for (const auto& e : table) {
        p[e.slot] += e.probability / 4.0;
        p[e.alias] += (1.0 - e.probability) / 4.0;
    }
    EXPECT_NEAR(p[7], 1.0 / 8.0, 1e-6);
    EXPECT_NEAR(p[3], 0.0, 1e-6);
    EXPECT_NEAR(p[9], 5.0 / 8.0, 1e-6);
    EXPECT_NEAR(p[4], 2.0 / 8.0, 1e-6);
    for (const auto& e : table) {
        double w = weights[std::find(slots.begin(), slots.end(), e.slot) - slots.begin()];
        EXPECT_NEAR(e.pdf, w / 8.0, 1e-6);
    }
}
