// The paged top grid (world/paged_top_grid.h): regions without a non-empty cell share one empty
// page, pages follow content and are reused, and a BrickGrid whose regions arrive and leave in
// any order (world/grid_streaming.h's writes) holds the same voxels and gives the same traversal
// hits, step for step, as the world generated directly.
#include "world/paged_top_grid.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <vector>

#include "core/hash.h"
#include "world/brick_grid.h"
#include "world/generators.h"
#include "world/random_worlds.h"
#include "world/ray_traversal.h"
#include "world/region_codec.h"

namespace {

using namespace engine::world;

TEST(PagedTopGrid, EmptyRegionsShareOnePageAndPagesAreReleasedAndReused) {
    PagedTopGrid top({40, 20, 40});  // 3 x 2 x 3 regions, the last ones clipped
    EXPECT_EQ(top.sizeInRegions(), glm::ivec3(3, 2, 3));
    EXPECT_EQ(top.livePages(), 0u);
    EXPECT_EQ(top.get({39, 19, 39}), shared::CELL_EMPTY);

    const glm::ivec3 a{1, 2, 3}, b{35, 17, 20};
    EXPECT_EQ(top.set(a, 7u), shared::CELL_EMPTY);
    EXPECT_EQ(top.get(a), 7u);
    EXPECT_EQ(top.livePages(), 1u);
    ASSERT_EQ(top.changedRegions().size(), 1u);
    EXPECT_EQ(top.changedRegions()[0], top.regionIndex(a));
    top.clearRegionChanges();

    // Emptied, the page stays until released (its cells may still be named by dirty lists).
    EXPECT_EQ(top.set(a, shared::CELL_EMPTY), 7u);
    EXPECT_TRUE(top.regionHasPage(a));
    top.releaseEmptyPages();
    EXPECT_FALSE(top.regionHasPage(a));
    EXPECT_EQ(top.livePages(), 0u);
    ASSERT_EQ(top.changedRegions().size(), 1u);
    top.clearRegionChanges();

    // Another region takes the freed page, with no cell of the old one left on it.
    top.set(b, 9u);
    EXPECT_EQ(top.pageCount(), 2u) << "the freed page is reused";
    EXPECT_EQ(top.get(b), 9u);
    EXPECT_EQ(top.get(a), shared::CELL_EMPTY);
    EXPECT_EQ(top.get(b + glm::ivec3(-1, 0, 0)), shared::CELL_EMPTY);
}

TEST(PagedTopGrid, RandomWritesAndReleasesMatchADenseModel) {
    const glm::ivec3 size{37, 21, 50};
    PagedTopGrid top(size);
    std::vector<std::uint32_t> dense(std::size_t(size.x) * size.y * size.z, shared::CELL_EMPTY);
    auto at = [&](glm::ivec3 c) -> std::uint32_t& {
        return dense[std::size_t(c.x) + std::size_t(size.x) * (c.y + std::size_t(size.y) * c.z)];
    };
    engine::Rng rng(17);
    for (int round = 0; round < 40; ++round) {
        // Writes cluster in a few regions per round, and half of them empty cells.
        const glm::ivec3 centre(rng.uniformInt(0, size.x - 1), rng.uniformInt(0, size.y - 1),
                                rng.uniformInt(0, size.z - 1));
        for (int i = 0; i < 2000; ++i) {
            const glm::ivec3 c =
                glm::clamp(centre + glm::ivec3(rng.uniformInt(-20, 20), rng.uniformInt(-20, 20),
                                               rng.uniformInt(-20, 20)),
                           glm::ivec3(0), size - 1);
            const std::uint32_t v =
                rng.nextFloat() < 0.5f ? shared::CELL_EMPTY : std::uint32_t(rng.uniformInt(1, 99));
            EXPECT_EQ(top.set(c, v), at(c));
            at(c) = v;
        }
        top.releaseEmptyPages();
        std::uint32_t occupiedRegions = 0;
        const glm::ivec3 regions = top.sizeInRegions();
        for (int rz = 0; rz < regions.z; ++rz)
            for (int ry = 0; ry < regions.y; ++ry)
                for (int rx = 0; rx < regions.x; ++rx) {
                    const CellRange r = regionCells({rx, ry, rz}, size);
                    bool occupied = false;
                    for (int z = r.min.z; z < r.max.z; ++z)
                        for (int y = r.min.y; y < r.max.y; ++y)
                            for (int x = r.min.x; x < r.max.x; ++x) {
                                ASSERT_EQ(top.get({x, y, z}), at({x, y, z}));
                                occupied |= at({x, y, z}) != shared::CELL_EMPTY;
                            }
                    EXPECT_EQ(top.regionHasPage(r.min), occupied) << "round " << round;
                    occupiedRegions += occupied;
                }
        EXPECT_EQ(top.livePages(), occupiedRegions) << "pages follow content";
    }
}

// 3 x 2 x 3 regions, the last ones clipped: a terrain with caves and scattered voxels.
BrickGrid directWorld() {
    BrickGrid grid({344, 200, 376});
    TerrainParams p;
    p.top = 1;
    p.soil = 2;
    p.rock = 3;
    p.baseHeight = 90;
    p.amplitude = 60;
    p.wavelength = 80;
    p.octaves = 4;
    p.seed = 11;
    generateTerrain(grid, p);
    engine::Rng rng(3);
    for (int i = 0; i < 6; ++i)
        fillSphere(grid, glm::vec3(rng.uniform(0, 344), rng.uniform(40, 120), rng.uniform(0, 376)),
                   rng.uniform(6, 20), kEmpty);
    for (int i = 0; i < 3000; ++i)
        grid.set({rng.uniformInt(0, 343), rng.uniformInt(0, 199), rng.uniformInt(0, 375)},
                 MaterialId(rng.uniformInt(1, 4)));
    grid.clearDirty();
    return grid;
}

std::vector<RegionKey> allRegions(const BrickGrid& grid) {
    std::vector<RegionKey> keys;
    const glm::ivec3 n = regionCount(grid.sizeInCells());
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) keys.push_back({x, y, z});
    return keys;
}

void shuffle(std::vector<RegionKey>& keys, engine::Rng& rng) {
    for (std::size_t i = keys.size(); i > 1; --i)
        std::swap(keys[i - 1], keys[std::size_t(rng.uniformInt(0, int(i) - 1))]);
}

// Every hit of `rays` in `got` equals `want`'s: hit, voxel, face, t (bit for bit), material and
// the number of steps.
int traversalDifferences(const BrickGrid& got, const BrickGrid& want,
                         const std::vector<Ray>& rays) {
    int differences = 0;
    for (const Ray& r : rays) {
        const RayHit a = traceRay(got, r), b = traceRay(want, r);
        differences += !(a.hit == b.hit && a.steps == b.steps &&
                         (!a.hit || (a.voxel == b.voxel && a.face == b.face && a.t == b.t &&
                                     a.material == b.material)));
    }
    return differences;
}

// Writes regions in the grid in `keys`' order (write) or erases them, a frame's clearDirty()
// after every 1-3 of them, as grid_streaming.h does: pages are released and reused in between.
void stream(BrickGrid& grid, const BrickGrid& source, const std::vector<RegionKey>& keys,
            bool write, engine::Rng& rng) {
    int inFrame = rng.uniformInt(1, 3);
    for (const RegionKey& k : keys) {
        if (write)
            writeRegion(snapshotRegion(source, k), grid);
        else
            eraseRegion(grid, k);
        if (--inFrame == 0) {
            grid.clearDirty();
            inFrame = rng.uniformInt(1, 3);
        }
    }
    grid.clearDirty();
}

TEST(PagedTopGrid, RegionsStreamedInAnyOrderEvictedAndReloadedGiveTheSameVoxelsAndHits) {
    const BrickGrid direct = directWorld();
    const std::vector<Ray> rays = testing_worlds::makeRays(direct, 5, 3000);
    int hits = 0;
    for (const Ray& r : rays) hits += traceRay(direct, r).hit;
    ASSERT_GT(hits, 1500);
    const std::uint32_t emptyPages = BrickGrid(direct.sizeInVoxels()).topGrid().pageCount();

    for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        engine::Rng rng(seed);
        BrickGrid grid(direct.sizeInVoxels());
        std::vector<RegionKey> keys = allRegions(direct);
        shuffle(keys, rng);
        stream(grid, direct, keys, true, rng);
        EXPECT_TRUE(grid == direct);
        EXPECT_EQ(traversalDifferences(grid, direct, rays), 0);

        for (int round = 0; round < 3; ++round) {
            // Evict a random half, in random order: the grid equals the direct world with those
            // regions erased, hit for hit.
            shuffle(keys, rng);
            const std::vector<RegionKey> evicted(keys.begin(), keys.begin() + keys.size() / 2);
            stream(grid, direct, evicted, false, rng);
            BrickGrid partial = direct;
            for (const RegionKey& k : evicted) eraseRegion(partial, k);
            partial.clearDirty();
            EXPECT_TRUE(grid == partial) << "round " << round;
            EXPECT_EQ(traversalDifferences(grid, partial, rays), 0) << "round " << round;
            EXPECT_EQ(grid.topGrid().livePages(), partial.topGrid().livePages())
                << "an evicted region keeps no page";

            // Reload them in another order.
            std::vector<RegionKey> back = evicted;
            shuffle(back, rng);
            stream(grid, direct, back, true, rng);
            EXPECT_TRUE(grid == direct) << "round " << round;
            EXPECT_EQ(traversalDifferences(grid, direct, rays), 0) << "round " << round;
        }
        EXPECT_EQ(grid.topGrid().livePages(), direct.topGrid().livePages());

        // Everything out: no page left, the table all on the empty page.
        stream(grid, direct, keys, false, rng);
        EXPECT_EQ(grid.topGrid().livePages(), 0u);
        EXPECT_EQ(grid.solidVoxels(), 0u);
        EXPECT_GT(grid.topGrid().pageCount(), emptyPages);
        EXPECT_LE(grid.topGrid().pageCount(), direct.topGrid().pageCount())
            << "freed pages are reused: never more than the most regions held at once";
    }
}

}  // namespace
