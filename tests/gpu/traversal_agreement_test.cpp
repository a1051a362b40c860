// GPU traversal (shaders/common/brick_traversal.glsl) against the CPU reference
// (engine/world/ray_traversal.cpp), hit for hit, on random worlds and awkward rays.
#include <algorithm>
#include <cstring>
#include <gtest/gtest.h>

#include "gpu/gpu_test_context.h"
#include "render/gpu_world.h"
#include "world/random_worlds.h"
#include "world/region_codec.h"

using namespace engine::world;
using namespace testing_worlds;
using gpu_testing::GpuTest;

namespace {

struct Agreement {
    int rays = 0, hits = 0, mismatches = 0, exactT = 0;
};

void compare(Scene& scene, const std::vector<Ray>& rays, std::uint32_t mode, Agreement& a,
             const char* label) {
    TraversalMode cpuMode = mode == shared::TRACE_MODE_HIERARCHICAL ? TraversalMode::Hierarchical
                                                                    : TraversalMode::PlainTwoLevel;
    std::vector<shared::TraceRayOutput> gpu = gpu_testing::traceOnGpu(scene, rays, mode);
    ASSERT_EQ(gpu.size(), rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        RayHit cpu = traceRay(scene.grid, rays[i], cpuMode);
        const shared::TraceRayOutput& g = gpu[i];
        bool gpuHit = g.data.x != 0;
        float gpuT;
        std::memcpy(&gpuT, &g.data.z, sizeof(float));
        ++a.rays;
        a.hits += cpu.hit;
        bool same = gpuHit == cpu.hit && (!cpu.hit || (glm::ivec3(g.voxel) == cpu.voxel &&
                                                       std::uint32_t(g.voxel.w) == cpu.face &&
                                                       g.data.y == cpu.material));
        if (same) {
            a.exactT += !cpu.hit || gpuT == cpu.t;
            continue;
        }
        ++a.mismatches;
        float tEnd = std::max(cpu.hit ? cpu.t : 0.0f, gpuHit ? gpuT : 0.0f) + 1.0f;
        EXPECT_LT(nearestEdgeDistance(rays[i], tEnd), 1e-4f)
            << label << " ray " << i << ": a mismatch that is not a grazing case; cpu hit "
            << cpu.hit << " voxel " << cpu.voxel.x << "," << cpu.voxel.y << "," << cpu.voxel.z
            << " gpu hit " << gpuHit << " voxel " << g.voxel.x << "," << g.voxel.y << ","
            << g.voxel.z;
    }
}

// Rays from all around (above the ground) at the centres of `targets`, so small edits get hit.
std::vector<Ray> raysAt(const std::vector<glm::ivec3>& targets, std::uint64_t seed, int perTarget) {
    engine::Rng rng(seed);
    std::vector<Ray> rays;
    for (glm::ivec3 target : targets) {
        for (int i = 0; i < perTarget; ++i) {
            glm::vec3 from = randomDirection(rng);
            from.y = std::abs(from.y);
            glm::vec3 centre = glm::vec3(target) + 0.5f;
            Ray r;
            r.origin = centre + from * rng.uniform(20.0f, 400.0f);
            r.direction = glm::normalize(centre - r.origin);
            rays.push_back(r);
        }
    }
    return rays;
}

// GPU against CPU with nothing tolerated: same hit, voxel, face, material, bit-identical t and
// the same number of steps.
int exactMismatches(Scene& scene, engine::render::GpuWorld& world, const std::vector<Ray>& rays,
                    int& hits) {
    std::vector<shared::TraceRayOutput> gpu = gpu_testing::traceOnGpu(world, scene, rays);
    int mismatches = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        RayHit cpu = traceRay(scene.grid, rays[i]);
        const shared::TraceRayOutput& g = gpu[i];
        float gpuT;
        std::memcpy(&gpuT, &g.data.z, sizeof(float));
        hits += cpu.hit;
        bool same = (g.data.x != 0) == cpu.hit && g.data.w == cpu.steps &&
                    (!cpu.hit ||
                     (glm::ivec3(g.voxel) == cpu.voxel && std::uint32_t(g.voxel.w) == cpu.face &&
                      g.data.y == cpu.material && gpuT == cpu.t));
        mismatches += !same;
    }
    return mismatches;
}

}  // namespace

class TraversalAgreement : public GpuTest {};

TEST_F(TraversalAgreement, GpuMatchesCpuOnRandomWorlds) {
    Agreement a;
    for (Kind kind : {Kind::Sparse, Kind::Dense, Kind::Homogeneous, Kind::Mixed}) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            Scene scene = gpu_testing::sceneWith(makeWorld(kind, seed * 7));
            compare(scene, makeRays(scene.grid, seed * 1000 + 17, 10000),
                    shared::TRACE_MODE_HIERARCHICAL, a, kindName(kind));
        }
    }
    std::printf("GPU vs CPU: %d rays, %d hits, %d mismatches (%.4f%%), %d with bit-identical t\n",
                a.rays, a.hits, a.mismatches, 100.0 * a.mismatches / a.rays, a.exactT);
    EXPECT_GE(a.rays, 100000);
    EXPECT_GT(a.hits, a.rays / 4);
    EXPECT_LE(a.mismatches * 10000, a.rays) << "more than 0.01% of rays disagree";
}

TEST_F(TraversalAgreement, PlainModeAlsoMatches) {
    Agreement a;
    Scene scene = gpu_testing::sceneWith(makeWorld(Kind::Mixed, 3));
    compare(scene, makeRays(scene.grid, 5, 10000), shared::TRACE_MODE_PLAIN, a, "plain");
    std::printf("plain mode: %d rays, %d mismatches\n", a.rays, a.mismatches);
    EXPECT_LE(a.mismatches * 10000, a.rays);
}

TEST_F(TraversalAgreement, BrickPagesBeyondTheFirstAreReached) {
    // More than BRICK_PAGE_BRICKS bricks: a checkerboard of single voxels, one per cell.
    BrickGrid grid({256, 96, 256});
    for (int z = 0; z < 32; ++z)
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 32; ++x)
                grid.set({x * 8 + 3, y * 8 + 3, z * 8 + 3}, MaterialId(1 + (x + y + z) % 7));
    ASSERT_GT(grid.liveBricks(), 2 * shared::BRICK_PAGE_BRICKS);
    Scene scene = gpu_testing::sceneWith(std::move(grid));
    std::vector<Ray> rays;
    for (int z = 0; z < 32; ++z)
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 32; ++x)
                rays.push_back(
                    Ray{{x * 8 + 3.5f, y * 8 + 3.5f, z * 8 + 0.25f}, {0.0f, 0.0f, 1.0f}});
    auto gpu = gpu_testing::traceOnGpu(scene, rays);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        RayHit cpu = traceRay(scene.grid, rays[i]);
        ASSERT_TRUE(cpu.hit);
        ASSERT_EQ(gpu[i].data.x, 1u) << "ray " << i;
        ASSERT_EQ(gpu[i].data.y, cpu.material) << "ray " << i;
        ASSERT_EQ(glm::ivec3(gpu[i].voxel), cpu.voxel) << "ray " << i;
    }
}

// Open air wide enough for every skip distance, traced through one GPU world that lives on, so
// the edits reach the GPU as incremental uploads of the super cells they dirtied: a voxel added
// in open air (distances around it shrink), a tower and a lone voxel removed (they grow back).
// GPU and CPU must still agree exactly, and the edited places must be seen.
TEST_F(TraversalAgreement, ExactAfterEditsUploadedIncrementally) {
    BrickGrid grid({384, 160, 384});  // 12 x 5 x 12 super cells
    fillBox(grid, Box{{0, 0, 0}, {384, 8, 384}}, 1);
    fillBox(grid, Box{{40, 8, 40}, {60, 40, 52}}, 2);
    grid.set({300, 100, 310}, 3);
    grid.clearDirty();
    Scene scene = gpu_testing::sceneWith(std::move(grid));
    ASSERT_EQ(*std::max_element(scene.grid.superCells().begin(), scene.grid.superCells().end()),
              shared::SUPER_SKIP_MAX);
    engine::render::GpuWorld world(gpu_testing::context());
    const glm::ivec3 added{200, 140, 200}, removed{300, 100, 310};
    const std::vector<glm::ivec3> targets{added, removed, {50, 30, 45}, {10, 7, 370}};

    int hits = 0;
    std::vector<Ray> rays = makeRays(scene.grid, 99, 6000);
    std::vector<Ray> aimed = raysAt(targets, 5, 500);
    rays.insert(rays.end(), aimed.begin(), aimed.end());
    EXPECT_EQ(exactMismatches(scene, world, rays, hits), 0) << "before the edits";

    scene.grid.set(added, 4);
    fillBox(scene.grid, Box{{40, 8, 40}, {60, 40, 52}}, kEmpty);
    scene.grid.set(removed, kEmpty);
    const std::size_t dirtySupers = scene.grid.dirtySuperCells().size();
    EXPECT_GT(dirtySupers, 0u);
    EXPECT_LT(dirtySupers, scene.grid.superCells().size() / 2)
        << "edits rewrite super cells near them only";
    EXPECT_EQ(exactMismatches(scene, world, rays, hits), 0) << "after the edits";

    int seen = 0;  // the new voxel is hit, the removed one is not
    for (const Ray& r : raysAt({added, removed}, 6, 50)) {
        RayHit h = traceRay(scene.grid, r);
        seen += h.hit && h.voxel == added;
        EXPECT_FALSE(h.hit && h.voxel == removed);
    }
    EXPECT_GT(seen, 40);
    EXPECT_GT(hits, 4000);
}

// Regions arriving and leaving in random order, each batch uploaded incrementally as vox play's
// streaming does (world/grid_streaming.h): pages are released and reused by other regions between
// syncs, so the GPU's region table and pages must follow. Exact after every batch.
TEST_F(TraversalAgreement, ExactWhileRegionsStreamInAndOutInRandomOrder) {
    const BrickGrid direct = makeWorld(Kind::Mixed, 21, {300, 136, 280});  // 3 x 2 x 3 regions
    std::vector<RegionKey> keys;
    const glm::ivec3 n = regionCount(direct.sizeInCells());
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) keys.push_back({x, y, z});
    Scene scene = gpu_testing::sceneWith(BrickGrid(direct.sizeInVoxels()));
    engine::render::GpuWorld world(gpu_testing::context());
    const std::vector<Ray> rays = makeRays(direct, 8, 2000);
    engine::Rng rng(4);
    auto shuffle = [&] {
        for (std::size_t i = keys.size(); i > 1; --i)
            std::swap(keys[i - 1], keys[std::size_t(rng.uniformInt(0, int(i) - 1))]);
    };
    int hits = 0, batches = 0;
    EXPECT_EQ(exactMismatches(scene, world, rays, hits), 0) << "empty";
    for (int round = 0; round < 3; ++round) {
        shuffle();
        // All in (regions already in are rewritten, unchanged), then a random half out, in
        // batches of 1-4 with a sync (and the grid's clearDirty) after each.
        for (int pass = 0; pass < 2; ++pass) {
            const std::size_t count = pass == 0 ? keys.size() : keys.size() / 2;
            for (std::size_t i = 0; i < count;) {
                const std::size_t end = std::min(count, i + std::size_t(rng.uniformInt(1, 4)));
                for (; i < end; ++i) {
                    if (pass == 0)
                        writeRegion(snapshotRegion(direct, keys[i]), scene.grid);
                    else
                        eraseRegion(scene.grid, keys[i]);
                }
                EXPECT_EQ(exactMismatches(scene, world, rays, hits), 0)
                    << "round " << round << " pass " << pass << " after " << i << " regions";
                ++batches;
            }
            if (pass == 0) EXPECT_TRUE(scene.grid == direct);
            shuffle();
        }
    }
    EXPECT_GT(batches, 20);
    EXPECT_GT(hits, 10000);
}
