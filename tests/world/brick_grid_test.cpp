#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/hash.h"
#include "world/brick_grid.h"

using namespace engine::world;

namespace {

// A dense model of the same world, for checking BrickGrid against something obviously right.
struct DenseWorld {
    glm::ivec3 size;
    std::vector<MaterialId> voxels;
    explicit DenseWorld(glm::ivec3 s) : size(s), voxels(std::size_t(s.x) * s.y * s.z, kEmpty) {}
    MaterialId& at(glm::ivec3 p) { return voxels[p.x + size.x * (p.y + size.y * std::size_t(p.z))]; }
};

}  // namespace

TEST(BrickGrid, SizeRoundsUpToWholeCells) {
    BrickGrid grid({20, 8, 9});
    EXPECT_EQ(grid.sizeInCells(), glm::ivec3(3, 1, 2));
    EXPECT_EQ(grid.sizeInVoxels(), glm::ivec3(24, 8, 16));
    EXPECT_EQ(grid.memory().topGridBytes, 6u * 4u);
    EXPECT_EQ(grid.liveBricks(), 0u);
}

TEST(BrickGrid, RandomSetGetMatchesDenseModel) {
    glm::ivec3 size{40, 24, 32};
    BrickGrid grid(size);
    DenseWorld dense(grid.sizeInVoxels());
    engine::Rng rng(42);
    for (int i = 0; i < 200000; ++i) {
        glm::ivec3 p{rng.uniformInt(0, 39), rng.uniformInt(0, 23), rng.uniformInt(0, 31)};
        MaterialId m = MaterialId(rng.uniformInt(0, 3));
        grid.set(p, m);
        dense.at(p) = m;
    }
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) ASSERT_EQ(grid.get({x, y, z}), dense.at({x, y, z})) << x << "," << y << "," << z;
    // Each super cell counts exactly the non-empty cells under it.
    std::vector<std::uint32_t> counts(grid.superCells().size(), 0);
    for (int z = 0; z < grid.sizeInCells().z; ++z)
        for (int y = 0; y < grid.sizeInCells().y; ++y)
            for (int x = 0; x < grid.sizeInCells().x; ++x)
                counts[grid.superCellIndex(glm::ivec3(x, y, z) >> 2)] += grid.cell({x, y, z}) != shared::CELL_EMPTY;
    EXPECT_TRUE(std::equal(counts.begin(), counts.end(), grid.superCells().begin()));
    // Every live brick's masks agree with its voxels.
    for (std::uint32_t c : grid.cells()) {
        if (!BrickGrid::cellIsBrick(c)) continue;
        std::uint32_t b = BrickGrid::cellBrick(c);
        EXPECT_EQ(grid.brickMask(b), BrickMask::build(grid.brickVoxels(b)));
        EXPECT_FALSE(isUniform(grid.brickVoxels(b))) << "a uniform brick should have collapsed";
    }
}

TEST(BrickGrid, OutOfBoundsReadsEmptyAndWritesAreIgnored) {
    BrickGrid grid({8, 8, 8});
    grid.set({-1, 0, 0}, 3);
    grid.set({8, 0, 0}, 3);
    EXPECT_EQ(grid.get({-1, 0, 0}), kEmpty);
    EXPECT_EQ(grid.get({0, 100, 0}), kEmpty);
    EXPECT_EQ(grid.liveBricks(), 0u);
    EXPECT_TRUE(grid.dirtyCells().empty());
}

TEST(BrickGrid, SettingEveryVoxelOfACellCollapsesIt) {
    BrickGrid grid({16, 8, 8});
    for (int z = 0; z < 8; ++z)
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                grid.set({x, y, z}, 5);
                if (x + y + z < 21) {
                    EXPECT_EQ(grid.liveBricks(), 1u);
                }
            }
    EXPECT_EQ(grid.liveBricks(), 0u);
    EXPECT_EQ(grid.cell({0, 0, 0}), shared::CELL_HOMOGENEOUS | 5u);
    EXPECT_EQ(grid.homogeneousCells(), 1u);
}

TEST(BrickMask, LevelsAgreeWithVoxels) {
    BrickVoxels v{};
    v[brickVoxelIndex({7, 0, 5})] = 1;
    BrickMask m = BrickMask::build(v);
    EXPECT_TRUE(m.voxel({7, 0, 5}));
    EXPECT_FALSE(m.voxel({6, 0, 5}));
    EXPECT_TRUE(m.block2({6, 1, 4}));
    EXPECT_FALSE(m.block2({5, 1, 4}));
    EXPECT_TRUE(m.block4({4, 3, 4}));
    EXPECT_FALSE(m.block4({3, 3, 4}));
}
