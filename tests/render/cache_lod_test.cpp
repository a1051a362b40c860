// The irradiance cache's level of detail on the host: which faces share a coarse entry (one face
// of an open, coplanar 2x2 patch), and what a coarse entry costs the ray budget.
#include "render/irradiance_cache/cache_lod.h"

#include <gtest/gtest.h>

#include "world/world_edits.h"

using engine::render::CacheKey;
using engine::render::coarsePatchKey;
using engine::render::packCacheKey;
using engine::render::staticKeyFor;
using engine::world::Box;
using engine::world::BrickGrid;

namespace {

constexpr std::uint32_t kUp = 3;  // face +y

BrickGrid floorGrid() {
    BrickGrid grid({16, 16, 16});
    engine::world::fillBox(grid, Box{{0, 0, 0}, {16, 2, 16}}, 1);
    return grid;
}

}  // namespace

TEST(CacheLod, AnOpenCoplanarPatchSharesOneKeyPerFace) {
    const BrickGrid grid = floorGrid();
    const CacheKey expected{{2, 1, 4}, shared::CACHE_SET_STATIC, 1 + kUp};
    for (glm::ivec3 v :
         {glm::ivec3(2, 1, 4), glm::ivec3(3, 1, 4), glm::ivec3(2, 1, 5), glm::ivec3(3, 1, 5)}) {
        EXPECT_EQ(staticKeyFor(grid, v, kUp, 50.0f, 10.0f), expected);
    }
    EXPECT_EQ(staticKeyFor(grid, {4, 1, 4}, kUp, 50.0f, 10.0f),
              (CacheKey{{4, 1, 4}, shared::CACHE_SET_STATIC, 1 + kUp}));
    // Near the camera, or with LOD off, each voxel keeps its own entry.
    EXPECT_EQ(staticKeyFor(grid, {3, 1, 5}, kUp, 5.0f, 10.0f),
              (CacheKey{{3, 1, 5}, shared::CACHE_SET_STATIC}));
    EXPECT_EQ(staticKeyFor(grid, {3, 1, 5}, kUp, 50.0f, 0.0f),
              (CacheKey{{3, 1, 5}, shared::CACHE_SET_STATIC}));
    // Coarse, fine and other faces' keys never collide in the table.
    const CacheKey side =
        *coarsePatchKey(grid, {0, 0, 4}, 0);  // face -x on the world's edge: open outside
    EXPECT_NE(packCacheKey(expected), packCacheKey(CacheKey{{2, 1, 4}, shared::CACHE_SET_STATIC}));
    EXPECT_NE(packCacheKey(expected), packCacheKey(side));
}

// A one-voxel wall standing on the patch closes it: its faces keep their own entries, so the wall
// cannot stand between two faces of one entry. The patch beside it stays coarse.
TEST(CacheLod, AWallOnThePatchKeepsItsFacesFine) {
    BrickGrid grid = floorGrid();
    engine::world::fillBox(grid, Box{{3, 2, 0}, {4, 8, 16}}, 1);  // a wall at x = 3
    EXPECT_FALSE(coarsePatchKey(grid, {2, 1, 4}, kUp).has_value());
    EXPECT_EQ(staticKeyFor(grid, {2, 1, 4}, kUp, 50.0f, 10.0f),
              (CacheKey{{2, 1, 4}, shared::CACHE_SET_STATIC}));
    EXPECT_TRUE(coarsePatchKey(grid, {4, 1, 4}, kUp).has_value());
    EXPECT_TRUE(coarsePatchKey(grid, {1, 1, 4}, kUp).has_value());
    // An unexposed patch (buried faces) is never coarse.
    EXPECT_FALSE(coarsePatchKey(grid, {2, 0, 4}, kUp).has_value());
}

// A coarse entry traces one face: the budget counts S rays for it, not 6 S.
TEST(CacheLod, ACoarseEntryCostsOneFaceOfTheBudget) {
    engine::render::CacheWork work;
    work.raysPerUpdate = 6 * 16;
    work.rayBudget = 2 * work.raysPerUpdate;  // one new voxel entry (a first update traces twice)
    std::vector<CacheKey> coarse, fine;
    for (int i = 0; i < 6; ++i) {
        coarse.push_back({{2 * i, 1, 0}, shared::CACHE_SET_STATIC, 1 + kUp});
        fine.push_back({{2 * i, 1, 2}, shared::CACHE_SET_STATIC});
    }
    engine::render::IrradianceCacheDirectory a(64), b(64);
    EXPECT_EQ(a.beginFrame(coarse, 0.0, 0.3f, work).update.size(), 6u);
    EXPECT_EQ(b.beginFrame(fine, 0.0, 0.3f, work).update.size(), 1u);
    EXPECT_EQ(a.entry(0).coarse, 1 + kUp);
}
