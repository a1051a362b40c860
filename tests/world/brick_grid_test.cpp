#include "world/brick_grid.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <vector>

#include "core/hash.h"

using namespace engine::world;

namespace {

// A dense model of the same world, for checking BrickGrid against something obviously right.
struct DenseWorld {
    glm::ivec3 size;
    std::vector<MaterialId> voxels;
    explicit DenseWorld(glm::ivec3 s) : size(s), voxels(std::size_t(s.x) * s.y * s.z, kEmpty) {}
    MaterialId& at(glm::ivec3 p) {
        return voxels[p.x + size.x * (p.y + size.y * std::size_t(p.z))];
    }
};

// Skip distance of every super cell computed from the top grid alone: 0 if any cell under it is
// non-empty, else the Chebyshev distance to the nearest occupied super cell, capped.
std::vector<std::uint32_t> bruteForceSkipDistances(const BrickGrid& grid) {
    const glm::ivec3 n = grid.sizeInSuperCells();
    std::vector<std::uint8_t> occupied(grid.superCells().size(), 0);
    for (int z = 0; z < grid.sizeInCells().z; ++z)
        for (int y = 0; y < grid.sizeInCells().y; ++y)
            for (int x = 0; x < grid.sizeInCells().x; ++x)
                if (grid.cell({x, y, z}) != shared::CELL_EMPTY)
                    occupied[grid.superCellIndex(glm::ivec3(x, y, z) >> 2)] = 1;
    std::vector<std::uint32_t> out(occupied.size(), shared::SUPER_SKIP_MAX);
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x)
                for (int oz = 0; oz < n.z; ++oz)
                    for (int oy = 0; oy < n.y; ++oy)
                        for (int ox = 0; ox < n.x; ++ox) {
                            if (!occupied[grid.superCellIndex({ox, oy, oz})]) continue;
                            glm::ivec3 d = glm::abs(glm::ivec3(ox - x, oy - y, oz - z));
                            std::uint32_t& o = out[grid.superCellIndex({x, y, z})];
                            o = std::min(o, std::uint32_t(std::max(d.x, std::max(d.y, d.z))));
                        }
    return out;
}

std::vector<std::uint32_t> skipDistances(const BrickGrid& grid) {
    return {grid.superCells().begin(), grid.superCells().end()};
}

}  // namespace

TEST(BrickGrid, SizeRoundsUpToWholeCells) {
    BrickGrid grid({20, 8, 9});
    EXPECT_EQ(grid.sizeInCells(), glm::ivec3(3, 1, 2));
    EXPECT_EQ(grid.sizeInVoxels(), glm::ivec3(24, 8, 16));
    EXPECT_EQ(grid.topGrid().livePages(), 0u) << "an empty world holds only the shared empty page";
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
            for (int x = 0; x < size.x; ++x)
                ASSERT_EQ(grid.get({x, y, z}), dense.at({x, y, z})) << x << "," << y << "," << z;
    // Each super cell counts exactly the non-empty cells under it.
    std::vector<std::uint32_t> counts(grid.superCellCounts().size(), 0);
    for (int z = 0; z < grid.sizeInCells().z; ++z)
        for (int y = 0; y < grid.sizeInCells().y; ++y)
            for (int x = 0; x < grid.sizeInCells().x; ++x)
                counts[grid.superCellIndex(glm::ivec3(x, y, z) >> 2)] +=
                    grid.cell({x, y, z}) != shared::CELL_EMPTY;
    EXPECT_TRUE(std::equal(counts.begin(), counts.end(), grid.superCellCounts().begin()));
    EXPECT_EQ(skipDistances(grid), bruteForceSkipDistances(grid));
    // Every live brick's masks agree with its voxels.
    for (std::uint32_t c : grid.denseCells()) {
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

// The skip distances rays use to cross open air follow every edit, and an edit rewrites only
// super cells near it (SUPER_SKIP_MAX - 1 away at most), never the whole super grid.
TEST(BrickGrid, SkipDistancesFollowEditsAndChangeOnlyNearThem) {
    BrickGrid grid({320, 96, 352});  // 10 x 3 x 11 super cells
    EXPECT_EQ(skipDistances(grid), bruteForceSkipDistances(grid));
    engine::Rng rng(7);
    const glm::ivec3 size = grid.sizeInVoxels();
    const int reach = int(shared::SUPER_SKIP_MAX) - 1;
    for (int round = 0; round < 60; ++round) {
        grid.clearDirty();
        // Edits stay in the first 128 voxels along x, so the far side keeps wide open air.
        glm::ivec3 p(rng.uniformInt(0, 127), rng.uniformInt(0, size.y - 1),
                     rng.uniformInt(0, size.z - 1));
        // Fill a voxel, or (every third round) empty a whole occupied 8^3 cell.
        bool carve = round % 3 == 2;
        if (carve) {
            glm::ivec3 c = p >> 3;
            for (int tries = 0; tries < 2000 && grid.cell(c) == shared::CELL_EMPTY; ++tries)
                c = glm::ivec3(rng.uniformInt(0, 127 / 8), rng.uniformInt(0, size.y / 8 - 1),
                               rng.uniformInt(0, size.z / 8 - 1));
            p = c * 8;
            grid.writeCellUniform(c, kEmpty);
        } else {
            grid.set(p, MaterialId(rng.uniformInt(1, 4)));
        }
        ASSERT_EQ(skipDistances(grid), bruteForceSkipDistances(grid)) << "round " << round;
        const glm::ivec3 edited = p >> int(shared::SUPER_SHIFT);
        for (std::uint32_t s : grid.dirtySuperCells()) {
            glm::ivec3 c(int(s) % grid.sizeInSuperCells().x,
                         int(s) / grid.sizeInSuperCells().x % grid.sizeInSuperCells().y,
                         int(s) / (grid.sizeInSuperCells().x * grid.sizeInSuperCells().y));
            glm::ivec3 d = glm::abs(c - edited);
            EXPECT_LE(std::max(d.x, std::max(d.y, d.z)), reach) << "round " << round;
        }
    }
    // Every distance occurred: the test covered occupied cells, near air and the capped far air.
    for (std::uint32_t k = 0; k <= shared::SUPER_SKIP_MAX; ++k)
        EXPECT_TRUE(std::count(grid.superCells().begin(), grid.superCells().end(), k) > 0) << k;
}
