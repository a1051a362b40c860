// Streaming regions (world/region_residency.h): a region holds the same voxels whether it was
// generated with the whole world, generated alone, read from a store, streamed in any order, or
// evicted and reloaded (seeded random orders); update() keeps the budget and loads around the eye.
#include "world/region_residency.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <gtest/gtest.h>

#include "core/hash.h"
#include "io/vdb_test_util.h"
#include "world/generators.h"
#include "world/region_store.h"
#include "world/store_region_source.h"
#include "world/terrain_region_source.h"
#include "world/test_terrain.h"

namespace {

using namespace engine::world;
namespace fs = std::filesystem;

// Clipped at every far edge: 47 x 25 x 42 cells, 3 x 2 x 3 regions.
constexpr glm::ivec3 kWorld{376, 200, 336};

TerrainParams terrain() { return vox_test::testTerrain(7); }

const BrickGrid& wholeWorld() {
    static const BrickGrid grid = [] {
        BrickGrid g(kWorld);
        generateTerrain(g, terrain());
        return g;
    }();
    return grid;
}

std::vector<RegionKey> allKeys() {
    const glm::ivec3 n = regionCount(wholeWorld().sizeInCells());
    std::vector<RegionKey> keys;
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) keys.push_back({x, y, z});
    return keys;
}

void expectSameRegion(const RegionSnapshot& a, const RegionSnapshot& b) {
    ASSERT_EQ(a.key, b.key);
    ASSERT_EQ(a.size, b.size);
    EXPECT_TRUE(a.cells == b.cells)
        << "region (" << a.key.x << ", " << a.key.y << ", " << a.key.z << ") cells differ";
    EXPECT_TRUE(a.bricks == b.bricks)
        << "region (" << a.key.x << ", " << a.key.y << ", " << a.key.z << ") bricks differ";
}

// Every resident region equals the whole-world generator's, and get() agrees voxel by voxel at
// seeded points (kEmpty where a region is not resident).
void expectResidentMatchesWorld(const RegionResidency& r, std::uint64_t seed) {
    for (RegionKey k : allKeys())
        if (const ResidentRegion* region = r.region(k))
            expectSameRegion(region->voxels(), snapshotRegion(wholeWorld(), k));
    engine::Rng rng(seed);
    for (int i = 0; i < 4000; ++i) {
        const glm::ivec3 p(rng.uniformInt(0, kWorld.x - 1), rng.uniformInt(0, kWorld.y - 1),
                           rng.uniformInt(0, kWorld.z - 1));
        const glm::ivec3 rk = p / (kRegionCells * kBrickDim);
        const bool resident = r.state({rk.x, rk.y, rk.z}) == RegionState::Resident;
        ASSERT_EQ(r.get(p), resident ? wholeWorld().get(p) : kEmpty)
            << "voxel " << p.x << " " << p.y << " " << p.z;
    }
}

void shuffle(std::vector<RegionKey>& keys, engine::Rng& rng) {
    for (std::size_t i = keys.size(); i > 1; --i)
        std::swap(keys[i - 1], keys[std::size_t(rng.uniformInt(0, int(i) - 1))]);
}

// A store of the whole world, one row per non-empty region (as vox import writes it).
fs::path writeStore(const vox_test::ScratchDir& dir) {
    const fs::path path = dir / "terrain.db";
    auto store = RegionStore::openOrCreate(path, kWorld);
    EXPECT_TRUE(store.ok()) << store.error().message;
    StoreCommit c;
    for (RegionKey k : allKeys()) {
        RegionSnapshot s = snapshotRegion(wholeWorld(), k);
        if (!s.empty()) c.put.push_back(encodeRegion(s));
    }
    EXPECT_TRUE(store->commit(c).ok());
    return path;
}

TEST(RegionResidency, TerrainRegionAloneEqualsTheWholeWorldGenerator) {
    TerrainRegionSource source(kWorld, terrain());
    for (RegionKey k : allKeys()) {
        auto region = source.load(k);
        ASSERT_TRUE(region.ok()) << region.error().message;
        expectSameRegion(*region, snapshotRegion(wholeWorld(), k));
    }
}

// Streams every region in a seeded random order, evicts a random half, reloads everything in
// another order, and checks the voxels after each step; for a generated and a stored world.
void streamInRandomOrders(const std::function<std::unique_ptr<RegionSource>()>& makeSource) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        engine::Rng rng(seed);
        RegionResidency r(makeSource(), {1e9f, std::uint64_t(1) << 40});
        std::vector<RegionKey> keys = allKeys();
        shuffle(keys, rng);
        r.request(keys);
        std::vector<std::string> errors;
        r.waitIdle(&errors);
        EXPECT_TRUE(errors.empty());
        ASSERT_EQ(r.residentRegions(), keys.size());
        expectResidentMatchesWorld(r, seed);
        for (int round = 0; round < 3; ++round) {
            shuffle(keys, rng);
            for (std::size_t i = 0; i < keys.size() / 2; ++i) r.evict(keys[i]);
            EXPECT_EQ(r.residentRegions(), keys.size() - keys.size() / 2);
            expectResidentMatchesWorld(r, seed * 10 + round);  // evicted: empty, never garbage
            shuffle(keys, rng);
            r.request(keys);
            r.waitIdle();
            ASSERT_EQ(r.residentRegions(), keys.size());
            expectResidentMatchesWorld(r, seed * 100 + round);
        }
    }
}

TEST(RegionResidency, GeneratedRegionsStreamInAnyOrderEvictAndReloadTheSame) {
    streamInRandomOrders([] { return std::make_unique<TerrainRegionSource>(kWorld, terrain()); });
}

TEST(RegionResidency, StoredRegionsStreamInAnyOrderEvictAndReloadTheSame) {
    vox_test::ScratchDir dir("residency");
    const fs::path path = writeStore(dir);
    streamInRandomOrders([&] {
        auto source = StoreRegionSource::open(path, 4);
        EXPECT_TRUE(source.ok()) << source.error().message;
        return std::make_unique<StoreRegionSource>(std::move(*source));
    });
}

// A seeded walk: after each step the eye's own region is resident (the budget holds a few), the
// budget holds, and every resident region is right.
TEST(RegionResidency, UpdateLoadsAroundTheEyeUnderTheBudget) {
    std::uint64_t oneRegion = 0;
    {
        RegionResidency probe(std::make_unique<TerrainRegionSource>(kWorld, terrain()),
                              {0.0f, std::uint64_t(1) << 40});
        const RegionKey k{1, 0, 1};
        probe.request(std::span(&k, 1));
        probe.waitIdle();
        oneRegion = probe.residentBytes();
    }
    ASSERT_GT(oneRegion, 0u);
    const ResidencySettings settings{150.0f, 3 * oneRegion};
    RegionResidency r(std::make_unique<TerrainRegionSource>(kWorld, terrain()), settings);
    engine::Rng rng(11);
    std::size_t evicted = 0;
    for (int step = 0; step < 30; ++step) {
        const glm::vec3 eye(rng.uniform(0.0f, kWorld.x), rng.uniform(40.0f, 150.0f),
                            rng.uniform(0.0f, kWorld.z));
        // Loads land between frames; a few frames at each stop let them in and settle the budget.
        for (int frame = 0; frame < 4; ++frame) {
            evicted += r.update(eye).evicted;
            r.waitIdle();
        }
        evicted += r.update(eye).evicted;
        EXPECT_LE(r.residentBytes(), settings.budgetBytes) << "step " << step;
        const glm::ivec3 at = glm::ivec3(eye) / (kRegionCells * kBrickDim);
        EXPECT_EQ(r.state({at.x, at.y, at.z}), RegionState::Resident) << "step " << step;
        expectResidentMatchesWorld(r, 1000 + step);
    }
    EXPECT_GT(evicted, 0u);
}

TEST(RegionResidency, ADamagedRowLoadsAsEmptyWithOneLine) {
    vox_test::ScratchDir dir("residency_bad");
    const fs::path path = writeStore(dir);
    {
        auto store = RegionStore::open(path, true);
        ASSERT_TRUE(store.ok());
        StoreCommit c;
        c.put.push_back(EncodedRegion{{1, 0, 1}, 100, {1, 2, 3, 4}});
        ASSERT_TRUE(store->commit(c).ok());
    }
    auto source = StoreRegionSource::open(path, 4);
    ASSERT_TRUE(source.ok());
    RegionResidency r(std::make_unique<StoreRegionSource>(std::move(*source)), {});
    const std::vector<RegionKey> keys = allKeys();
    r.request(keys);
    std::vector<std::string> errors;
    r.waitIdle(&errors);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].find("region (1, 0, 1)"), std::string::npos) << errors[0];
    EXPECT_EQ(r.state({1, 0, 1}), RegionState::Failed);
    EXPECT_EQ(r.get({200, 60, 200}), kEmpty);
    EXPECT_EQ(r.residentRegions(), keys.size() - 1);
}

}  // namespace

namespace {

// Not a test: the figures in docs/WORLD_STORE.md ("Streaming: the CPU side"). A walk of 8 km
// across a 16 384 x 512 x 16 384 terrain generated region by region, 64 voxels a step, the loader
// drained after each step. Run with
//   store_tests --gtest_also_run_disabled_tests --gtest_filter='*MeasureTerrainWalk*'
TEST(RegionResidency, DISABLED_MeasureTerrainWalk) {
    const glm::ivec3 world{16384, 512, 16384};
    TerrainParams p = terrain();
    p.wavelength = 300;
    p.octaves = 5;
    for (float radius : {512.0f, 1024.0f, 2048.0f}) {
        const ResidencySettings settings{radius, std::uint64_t(3) << 29};  // 1.5 GiB
        RegionResidency r(std::make_unique<TerrainRegionSource>(world, p), settings);
        std::uint64_t peakBytes = 0;
        std::size_t peakRegions = 0, loaded = 0, evicted = 0;
        const auto t0 = std::chrono::steady_clock::now();
        for (int step = 0; step <= 8192 / 64; ++step) {
            const glm::vec3 eye(4096.0f + 64.0f * step, 150.0f, 8192.0f);
            auto report = r.update(eye);
            loaded += r.waitIdle();
            evicted += report.evicted;
            evicted += r.update(eye).evicted;
            peakBytes = std::max(peakBytes, r.residentBytes());
            peakRegions = std::max(peakRegions, r.residentRegions());
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf(
            "radius %.0f: %zu regions loaded (%.1f ms each, loader and frame together), %zu "
            "evicted; peak %zu resident, %.1f MiB (budget %.0f MiB); table %.1f KiB\n",
            double(radius), loaded, 1000.0 * seconds / double(std::max<std::size_t>(loaded, 1)),
            evicted, peakRegions, double(peakBytes) / (1 << 20),
            double(settings.budgetBytes) / (1 << 20), double(r.tableBytes()) / 1024.0);
    }
}

}  // namespace
