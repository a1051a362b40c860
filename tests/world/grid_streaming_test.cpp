// A grid that streams its regions (world/grid_streaming.h): once everything near the eye has
// arrived it equals the world loaded whole; regions that leave are empty again with their bricks
// back in the pool; streaming never stamps an edit a save would write; an edited region is pinned
// until saved, and its edit survives eviction, reload and a restart from the store.
#include "world/grid_streaming.h"

#include <gtest/gtest.h>

#include "io/vdb_test_util.h"
#include "world/generators.h"
#include "world/region_store.h"
#include "world/store_region_source.h"
#include "world/terrain_region_source.h"
#include "world/test_terrain.h"

namespace {

using namespace engine::world;
namespace fs = std::filesystem;

// 4 x 2 x 4 regions, the last ones clipped.
constexpr glm::ivec3 kWorld{480, 200, 456};

TerrainParams terrain() { return vox_test::testTerrain(5); }

const BrickGrid& wholeWorld() {
    static const BrickGrid grid = [] {
        BrickGrid g(kWorld);
        generateTerrain(g, terrain());
        g.clearDirty();
        return g;
    }();
    return grid;
}

// Frames until everything asked for is loaded and in the grid (the loader drained in between).
void settle(GridStreaming& s, glm::vec3 eye, BrickGrid& grid) {
    for (int frame = 0; frame < 1000; ++frame) {
        s.residency().waitIdle();
        const GridStreamingReport r = s.update(eye, grid);
        grid.clearDirty();  // what the GPU mirror does after its upload
        if (r.pending == 0 && r.waiting == 0 && r.arrived == 0 && r.left == 0) return;
    }
    FAIL() << "streaming did not settle";
}

// The grid's voxels region by region: the world's where the region is in the grid, else empty.
void expectGridFollowsResidency(const GridStreaming& s, const BrickGrid& grid,
                                const BrickGrid& world) {
    const glm::ivec3 n = regionCount(grid.sizeInCells());
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) {
                const RegionKey k{x, y, z};
                const RegionSnapshot got = snapshotRegion(grid, k);
                if (s.inGrid(k)) {
                    const RegionSnapshot want = snapshotRegion(world, k);
                    EXPECT_TRUE(got.cells == want.cells && got.bricks == want.bricks)
                        << "region " << x << " " << y << " " << z << " differs";
                } else {
                    EXPECT_TRUE(got.empty()) << "region " << x << " " << y << " " << z
                                             << " left the grid but is not empty";
                }
            }
}

TEST(GridStreaming, StreamedGridEqualsTheWorldLoadedWholeAndEvictionsEmptyIt) {
    BrickGrid grid(kWorld);
    GridStreaming s(std::make_unique<TerrainRegionSource>(kWorld, terrain()),
                    {1e6f, std::uint64_t(1) << 40}, 3);
    const std::uint32_t epoch = grid.closeEditEpoch();
    settle(s, glm::vec3(kWorld) * 0.5f, grid);
    EXPECT_EQ(s.regionsInGrid(), 32u);
    EXPECT_TRUE(grid == wholeWorld());
    EXPECT_EQ(grid.liveBricks(), wholeWorld().liveBricks());
    EXPECT_TRUE(grid.regionsEditedAfter(epoch).empty()) << "streaming stamped an edit";

    // A budget of about two regions, the eye in a corner: the rest leaves, its bricks freed.
    const ResidencySettings tight{100.0f, s.bytes() / 4};
    GridStreaming t(std::make_unique<TerrainRegionSource>(kWorld, terrain()), tight, 2);
    BrickGrid small(kWorld);
    settle(t, glm::vec3(kWorld) * 0.5f, small);
    settle(t, glm::vec3(10.0f, 120.0f, 10.0f), small);
    EXPECT_TRUE(t.inGrid({0, 0, 0}));
    EXPECT_LT(t.regionsInGrid(), 32u);
    expectGridFollowsResidency(t, small, wholeWorld());
    EXPECT_LE(t.bytes(), tight.budgetBytes);
    // Freed bricks are reused: the pool never holds more than the regions in it at their peak.
    std::uint32_t capacity = small.brickCapacity();
    settle(t, glm::vec3(kWorld.x - 10.0f, 120.0f, kWorld.z - 10.0f), small);
    expectGridFollowsResidency(t, small, wholeWorld());
    EXPECT_LE(small.brickCapacity(), std::max(capacity, wholeWorld().liveBricks()));
    EXPECT_TRUE(small.regionsEditedAfter(epoch).empty());
    EXPECT_TRUE(t.boxInGrid({glm::ivec3(kWorld.x - 12, 100, kWorld.z - 12),
                             glm::ivec3(kWorld.x - 8, 104, kWorld.z - 8)}));
    EXPECT_FALSE(t.boxInGrid({glm::ivec3(0), glm::ivec3(4)}));
}

// The per-frame brick limit spreads arrivals over frames: with every region loaded, each frame
// writes regions whose bricks stay within the limit, or one region alone if it has more; the
// grid's dirty bricks (what the GPU uploads) are exactly those; and the grid ends equal to the
// world loaded whole.
TEST(GridStreaming, BricksPerFrameSpreadArrivalsOverFrames) {
    BrickGrid grid(kWorld);
    const std::size_t limit = 600;
    GridStreaming s(std::make_unique<TerrainRegionSource>(kWorld, terrain()),
                    {1e6f, std::uint64_t(1) << 40}, 32, limit);
    const glm::vec3 eye(10.0f, 60.0f, 10.0f);
    s.update(eye, grid);  // asks for every region
    s.residency().waitIdle();
    ASSERT_EQ(s.residency().residentRegions(), 32u);
    std::size_t frames = 0, alone = 0, arrived = 0;
    while (arrived < 32u) {
        ASSERT_LT(frames, 32u) << "a frame took no region";
        const GridStreamingReport r = s.update(eye, grid);
        ASSERT_GE(r.arrived, 1u);
        EXPECT_EQ(grid.dirtyBricks().size(), r.bricks);
        if (r.arrived == 1 && r.bricks > limit)
            ++alone;
        else
            EXPECT_LE(r.bricks, limit);
        arrived += r.arrived;
        ++frames;
        grid.clearDirty();
    }
    EXPECT_EQ(s.regionsInGrid(), 32u);
    EXPECT_TRUE(grid == wholeWorld());
    // The limit did split the arrivals (32 regions a frame were allowed).
    EXPECT_GT(frames, 2u);
    std::printf("%zu frames, %zu with one region over the limit, %u bricks\n", frames, alone,
                wholeWorld().liveBricks());
}

// What the renderer reads to see an edit (BrickGrid's dirty and touched lists, which FrameChanges,
// the emitter list, ReGIR, the irradiance cache and DVF follow) holds every cell of a region that
// arrives and of one that leaves.
TEST(GridStreaming, ArrivalsAndEvictionsMarkCellsLikeAnEdit) {
    BrickGrid grid(kWorld);
    GridStreaming s(std::make_unique<TerrainRegionSource>(kWorld, terrain()),
                    {0.0f, std::uint64_t(1) << 40}, 4);
    const glm::vec3 eye(10.0f, 60.0f, 10.0f);
    const RegionKey k{0, 0, 0};
    s.update(eye, grid);
    s.residency().waitIdle();
    ASSERT_EQ(s.update(eye, grid).arrived, 1u);
    const RegionSnapshot want = snapshotRegion(wholeWorld(), k);
    std::size_t solidCells = 0;
    for (std::uint32_t c : want.cells) solidCells += c != shared::CELL_EMPTY;
    ASSERT_GT(solidCells, 0u);
    EXPECT_EQ(grid.touchedCells().size(), solidCells);
    EXPECT_EQ(grid.dirtyCells().size(), solidCells);
    EXPECT_EQ(grid.dirtyBricks().size(), want.bricks.size());
    grid.clearDirty();
    s.residency().evict(k);
    ASSERT_EQ(s.update(eye + glm::vec3(1e4f), grid).left, 1u);
    EXPECT_EQ(grid.touchedCells().size(), solidCells);
    EXPECT_EQ(grid.dirtyCells().size(), solidCells);
    EXPECT_EQ(grid.liveBricks(), 0u);
}

// The acceptance's "edits made in a region survive its eviction, reload and a restart": edit,
// walk away (pinned: not evicted), save, walk away (evicted), walk back, compare; restart.
TEST(GridStreaming, EditsSurviveEvictionReloadAndRestart) {
    vox_test::ScratchDir dir("grid_streaming");
    const fs::path path = dir / "w.db";
    {
        auto store = RegionStore::openOrCreate(path, kWorld);
        ASSERT_TRUE(store.ok()) << store.error().message;
        StoreCommit c;
        const glm::ivec3 n = regionCount(wholeWorld().sizeInCells());
        for (int z = 0; z < n.z; ++z)
            for (int y = 0; y < n.y; ++y)
                for (int x = 0; x < n.x; ++x)
                    if (RegionSnapshot r = snapshotRegion(wholeWorld(), {x, y, z}); !r.empty())
                        c.put.push_back(encodeRegion(r));
        ASSERT_TRUE(store->commit(c).ok());
    }
    auto open = [&] {
        auto source = StoreRegionSource::open(path, 4);
        EXPECT_TRUE(source.ok());
        return std::make_unique<StoreRegionSource>(std::move(*source));
    };
    // The budget holds the column of regions around the eye and little more: walking away must
    // evict it unless it is pinned.
    const glm::vec3 here(10.0f, 120.0f, 10.0f), away(kWorld.x - 10.0f, 120.0f, kWorld.z - 10.0f);
    std::uint64_t column = 0;
    {
        GridStreaming probe(open(), {60.0f, std::uint64_t(1) << 40}, 8);
        BrickGrid g(kWorld);
        settle(probe, here, g);
        column = probe.bytes();
    }
    const ResidencySettings tight{60.0f, column + column / 20};
    const RegionKey edited{0, 0, 0};
    glm::ivec3 voxel(20, 127, 20);  // the ground's top voxel there, painted another material
    while (wholeWorld().get(voxel) == kEmpty) --voxel.y;
    const MaterialId paint = wholeWorld().get(voxel) == 3 ? 2 : 3;
    BrickGrid grid(kWorld);
    GridStreaming s(open(), tight, 4);
    std::uint32_t saved = grid.closeEditEpoch();
    settle(s, here, grid);
    ASSERT_TRUE(s.inGrid(edited));
    grid.set(voxel, paint);
    BrickGrid want = wholeWorld();
    want.set(voxel, paint);

    // Dirty: pinned, so it stays in the grid far from the eye, beyond the budget.
    std::vector<RegionKey> dirty = grid.regionsEditedAfter(saved);
    ASSERT_EQ(dirty, std::vector<RegionKey>{edited});
    s.pin(dirty);
    settle(s, away, grid);
    EXPECT_TRUE(s.inGrid(edited));
    EXPECT_EQ(grid.get(voxel), paint);

    // Saved (what vox play's saver commits): unpinned, evicted, reloaded with the edit.
    {
        auto store = RegionStore::open(path, true);
        ASSERT_TRUE(store.ok());
        StoreCommit c;
        c.put.push_back(encodeRegion(snapshotRegion(grid, edited)));
        ASSERT_TRUE(store->commit(c).ok());
    }
    saved = grid.closeEditEpoch();
    s.pin(grid.regionsEditedAfter(saved));
    // Walking on (a region's width or more, so the residency asks again after the budget held it
    // back): the budget now evicts the edited region, the farthest.
    settle(s, glm::vec3(kWorld.x - 10.0f, 120.0f, kWorld.z * 0.5f), grid);
    EXPECT_FALSE(s.inGrid(edited));
    EXPECT_EQ(grid.get(voxel), kEmpty);
    settle(s, here, grid);
    ASSERT_TRUE(s.inGrid(edited));
    EXPECT_EQ(grid.get(voxel), paint);
    expectGridFollowsResidency(s, grid, want);
    EXPECT_TRUE(grid.regionsEditedAfter(saved).empty());

    // A restart streams it from the store.
    BrickGrid again(kWorld);
    GridStreaming restarted(open(), {1e6f, std::uint64_t(1) << 40}, 8);
    settle(restarted, here, again);
    EXPECT_TRUE(again == want);
}

}  // namespace
