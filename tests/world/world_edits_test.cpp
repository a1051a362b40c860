#include "world/world_edits.h"

#include <algorithm>
#include <gtest/gtest.h>

#include "core/hash.h"

using namespace engine::world;

TEST(WorldEdits, FillBoxAlignedToCellsTakesNoBrickStorage) {
    BrickGrid grid({64, 64, 64});
    fillBox(grid, Box{{8, 16, 0}, {40, 48, 24}}, 3);  // 4 x 4 x 3 cells, all aligned
    EXPECT_EQ(grid.liveBricks(), 0u);
    EXPECT_EQ(grid.brickCapacity(), 0u);
    EXPECT_EQ(grid.homogeneousCells(), 48u);
    EXPECT_EQ(grid.solidVoxels(), 32u * 32u * 24u);
    EXPECT_TRUE(grid.dirtyBricks().empty());
    EXPECT_EQ(grid.dirtyCells().size(), 48u);
}

TEST(WorldEdits, CarvingOneVoxelSplitsOnlyThatBrick) {
    BrickGrid grid({64, 64, 64});
    fillBox(grid, Box{{0, 0, 0}, {32, 32, 32}}, 2);
    grid.clearDirty();
    grid.set({9, 9, 9}, kEmpty);
    EXPECT_EQ(grid.liveBricks(), 1u);
    EXPECT_EQ(grid.homogeneousCells(), 63u);
    EXPECT_EQ(grid.get({9, 9, 9}), kEmpty);
    EXPECT_EQ(grid.get({10, 9, 9}), 2);
    ASSERT_EQ(grid.dirtyBricks().size(), 1u);
    ASSERT_EQ(grid.dirtyCells().size(), 1u);
    EXPECT_EQ(grid.dirtyCells()[0], grid.cellIndex({1, 1, 1}));
    // Filling it back collapses the brick into a homogeneous cell again.
    grid.set({9, 9, 9}, 2);
    EXPECT_EQ(grid.liveBricks(), 0u);
    EXPECT_EQ(grid.cell({1, 1, 1}), shared::CELL_HOMOGENEOUS | 2u);
}

TEST(WorldEdits, FreedBricksAreReused) {
    BrickGrid grid({64, 8, 8});
    grid.set({1, 1, 1}, 1);
    grid.set({9, 1, 1}, 1);
    ASSERT_EQ(grid.brickCapacity(), 2u);
    std::uint32_t first = BrickGrid::cellBrick(grid.cell({0, 0, 0}));
    grid.set({1, 1, 1}, kEmpty);  // brick 0 collapses to empty and is freed
    EXPECT_EQ(grid.liveBricks(), 1u);
    grid.set({17, 2, 2}, 4);  // a new brick takes the freed slot
    EXPECT_EQ(grid.brickCapacity(), 2u);
    EXPECT_EQ(BrickGrid::cellBrick(grid.cell({2, 0, 0})), first);
    EXPECT_EQ(grid.get({17, 2, 2}), 4);
    EXPECT_EQ(grid.get({9, 1, 1}), 1);
}

TEST(WorldEdits, FillSphereMatchesVoxelCentreRule) {
    BrickGrid grid({48, 48, 48});
    glm::vec3 c{23.3f, 20.0f, 25.7f};
    float r = 13.5f;
    fillSphere(grid, c, r, 7);
    std::uint64_t expected = 0;
    for (int z = 0; z < 48; ++z)
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x) {
                glm::vec3 d = glm::vec3(x, y, z) + 0.5f - c;
                bool inside = glm::dot(d, d) <= r * r;
                expected += inside;
                ASSERT_EQ(grid.get({x, y, z}), inside ? 7 : kEmpty) << x << "," << y << "," << z;
            }
    EXPECT_EQ(grid.solidVoxels(), expected);
    EXPECT_GT(grid.homogeneousCells(), 0u) << "the sphere's core should need no brick storage";
}

TEST(WorldEdits, ReplaceMaterialOnlyTouchesThatMaterialInTheRegion) {
    BrickGrid grid({32, 32, 32});
    fillBox(grid, Box{{0, 0, 0}, {32, 8, 32}}, 1);
    fillBox(grid, Box{{4, 8, 4}, {12, 20, 12}}, 2);
    replaceMaterial(grid, Box{{0, 0, 0}, {16, 32, 32}}, 1, 3);
    EXPECT_EQ(grid.get({0, 0, 0}), 3);
    EXPECT_EQ(grid.get({15, 7, 31}), 3);
    EXPECT_EQ(grid.get({16, 0, 0}), 1);
    EXPECT_EQ(grid.get({5, 10, 5}), 2);
    // The cell-aligned half stays homogeneous: no brick was needed.
    EXPECT_EQ(grid.cell({0, 0, 0}), shared::CELL_HOMOGENEOUS | 3u);
}

TEST(WorldEdits, CopyPasteRoundTripsARegion) {
    BrickGrid grid({64, 32, 64});
    engine::Rng rng(9);
    for (int i = 0; i < 3000; ++i)
        grid.set({rng.uniformInt(0, 20), rng.uniformInt(0, 20), rng.uniformInt(0, 20)},
                 MaterialId(rng.uniformInt(1, 4)));
    fillBox(grid, Box{{0, 0, 0}, {8, 8, 8}}, 6);
    Box region{{0, 0, 0}, {21, 21, 21}};
    BrickGrid clip = copyRegion(grid, region);
    pasteRegion(grid, clip, {37, 5, 40}, false);
    for (int z = 0; z < 21; ++z)
        for (int y = 0; y < 21; ++y)
            for (int x = 0; x < 21; ++x)
                ASSERT_EQ(grid.get(glm::ivec3(37 + x, 5 + y, 40 + z)), grid.get({x, y, z}));
    // skipEmpty keeps what is under the clip's holes.
    fillBox(grid, Box{{0, 0, 40}, {64, 32, 64}}, 5);
    pasteRegion(grid, clip, {37, 5, 40}, true);
    for (int z = 0; z < 21; ++z)
        for (int y = 0; y < 21; ++y)
            for (int x = 0; x < 21; ++x) {
                MaterialId src = grid.get({x, y, z});
                ASSERT_EQ(grid.get(glm::ivec3(37 + x, 5 + y, 40 + z)), src == kEmpty ? 5 : src);
            }
}

TEST(WorldEdits, UnchangedCellsAreNotDirtied) {
    BrickGrid grid({32, 32, 32});
    fillBox(grid, Box{{0, 0, 0}, {20, 20, 20}}, 1);
    grid.clearDirty();
    fillBox(grid, Box{{0, 0, 0}, {20, 20, 20}}, 1);
    EXPECT_TRUE(grid.dirtyBricks().empty());
    EXPECT_TRUE(grid.dirtyCells().empty());
}
