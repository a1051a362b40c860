// VctBlockList (render/vct/vct_block_list.h): the blocks of 4^3 texels vct.classify visits. The
// texels new to a level after it moved, the blocks that meet a box, and the content test against a
// cell-by-cell scan of the grid.
#include "render/vct/vct_block_list.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <random>
#include <vector>

using engine::render::VctBlockList;
using engine::world::BrickGrid;

namespace {

constexpr int kAxis = int(shared::VCT_BLOCKS_PER_AXIS);

std::uint32_t blockIndex(std::uint32_t level, int x, int y, int z) {
    return level * shared::VCT_BLOCKS_PER_LEVEL + std::uint32_t(x + kAxis * (y + kAxis * z));
}

std::vector<std::uint32_t> listed(VctBlockList& list) {
    const auto b = list.blocks();
    return {b.begin(), b.end()};
}

}  // namespace

// A level that moved one texel along +x reuses the slots of all but its last texel column: only
// the last column of blocks holds new texels. Moved a whole level away, or with another texel
// size, every block is new; not moved, none.
TEST(VctBlockList, NewTexelsAreTheSlabTheLevelMovedInto) {
    VctBlockList list;
    const glm::ivec4 before(-64, 0, 32, 4), now(-60, 0, 32, 4);  // level 1: 4-voxel texels
    list.clear();
    list.addNew(1, now, before);
    std::vector<std::uint32_t> expected;
    for (int z = 0; z < kAxis; ++z)
        for (int y = 0; y < kAxis; ++y) expected.push_back(blockIndex(1, kAxis - 1, y, z));
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(listed(list), expected);

    // Moved down by five texels: the first two rows of blocks (y 0 and 1) hold new texels.
    list.clear();
    list.addNew(1, glm::ivec4(-64, -20, 32, 4), before);
    EXPECT_EQ(list.blocks().size(), std::size_t(2 * kAxis * kAxis));
    for (std::uint32_t b : list.blocks())
        EXPECT_LT((b % shared::VCT_BLOCKS_PER_LEVEL) / kAxis % kAxis, 2u) << b;

    list.clear();
    list.addNew(1, before, before);
    EXPECT_TRUE(list.blocks().empty());
    list.addNew(1, before, glm::ivec4(-64, 0, 32, 2));
    EXPECT_EQ(list.blocks().size(), std::size_t(shared::VCT_BLOCKS_PER_LEVEL));
}

// A box lists the blocks it meets, in the level's voxels; an empty box none.
TEST(VctBlockList, BoxListsTheBlocksItMeets) {
    VctBlockList list;
    const glm::ivec4 level0(10, 20, 30, 2);  // blocks of 8 voxels
    list.clear();
    list.addBox(0, level0, glm::ivec3(18, 20, 30), glm::ivec3(19, 29, 31));  // x 1, y 0..1, z 0
    EXPECT_EQ(listed(list),
              (std::vector<std::uint32_t>{blockIndex(0, 1, 0, 0), blockIndex(0, 1, 1, 0)}));
    list.clear();
    list.addBox(0, level0, glm::ivec3(5), glm::ivec3(5));
    EXPECT_TRUE(list.blocks().empty());
    list.addAll(2);
    EXPECT_EQ(list.blocks().size(), std::size_t(2 * shared::VCT_BLOCKS_PER_LEVEL));
}

// holdsCell against every cell of the box, on random boxes over a sparse random grid (inside,
// across and outside its bounds); and addContent lists exactly the blocks whose box holds one.
TEST(VctBlockList, ContentIsTheBlocksHoldingAnOccupiedCell) {
    BrickGrid grid({200, 96, 144});
    std::mt19937 rng(7);
    for (int i = 0; i < 40; ++i) grid.set({int(rng() % 200), int(rng() % 96), int(rng() % 144)}, 1);
    const auto scan = [&](glm::ivec3 lo, glm::ivec3 hi) {
        for (int z = 0; z < grid.sizeInCells().z; ++z)
            for (int y = 0; y < grid.sizeInCells().y; ++y)
                for (int x = 0; x < grid.sizeInCells().x; ++x) {
                    const glm::ivec3 c(x, y, z);
                    if (glm::any(glm::lessThanEqual(hi, c * 8)) ||
                        glm::any(glm::greaterThanEqual(lo, c * 8 + 8)))
                        continue;
                    if (grid.cell(c) != shared::CELL_EMPTY) return true;
                }
        return false;
    };
    int holding = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::ivec3 lo(int(rng() % 260) - 30, int(rng() % 130) - 30, int(rng() % 200) - 30);
        const glm::ivec3 hi = lo + glm::ivec3(1 + int(rng() % 70));
        const bool holds = VctBlockList::holdsCell(grid, lo, hi);
        EXPECT_EQ(holds, scan(lo, hi))
            << lo.x << "," << lo.y << "," << lo.z << " size " << hi.x - lo.x;
        holding += holds ? 1 : 0;
    }
    EXPECT_GT(holding, 20);  // both answers were tested
    EXPECT_LT(holding, 380);

    VctBlockList list;
    const glm::ivec4 level2(-24, -8, 16, 8);  // blocks of 32 voxels
    const auto scanned = [&] {
        std::vector<std::uint32_t> blocks;
        for (int z = 0; z < kAxis; ++z)
            for (int y = 0; y < kAxis; ++y)
                for (int x = 0; x < kAxis; ++x) {
                    const glm::ivec3 lo = glm::ivec3(level2) + glm::ivec3(x, y, z) * 32;
                    if (scan(lo, lo + 32)) blocks.push_back(blockIndex(2, x, y, z));
                }
        return blocks;
    };
    const std::vector<std::uint32_t> before = scanned();
    list.clear();
    list.addContent(2, level2, grid, 1);
    EXPECT_FALSE(before.empty());
    EXPECT_EQ(listed(list), before);
    // Cached per placement and grid version: an edit shows under a new version.
    grid.set({180, 90, 100}, 1);
    const std::vector<std::uint32_t> after = scanned();
    ASSERT_NE(after, before);
    list.clear();
    list.addContent(2, level2, grid, 2);
    EXPECT_EQ(listed(list), after);
}
